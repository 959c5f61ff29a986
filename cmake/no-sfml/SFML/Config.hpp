// Placed first on abalike_core's include path: every SFML header includes <SFML/Config.hpp>,
// so any SFML include in the core stops the build here.
#error "abalike_core must not use SFML: drawing belongs in src/app/"

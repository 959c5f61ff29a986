#include "FuzzInput.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

/// The level loader must answer any bytes with a level or a LevelLoadError. A level it accepts must also build a
/// world that a launch and two seconds of steps cannot drive to NaN.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace abalike;
    LevelDef level;
    try
    {
        level = parseLevel(fuzz::asText(data, size), "fuzz.json", Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        if (e.issues().empty())
            fuzz::fail("LevelLoadError without an issue");
        return 0;
    }
    GameSession session(level);
    constexpr int kSteps = 120;
    if (session.currentBird() != nullptr)
        session.launch(40.0, 0.8 * session.maxLaunchSpeed());
    for (int i = 0; i < kSteps && !session.finished(); ++i)
        session.step();
    if (session.world().hasNonFiniteState())
        fuzz::fail("a level the loader accepted produced a non-finite body state");
    return 0;
}

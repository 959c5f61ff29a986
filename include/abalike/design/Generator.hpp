#pragma once

#include <abalike/design/ModelPlayer.hpp>
#include <abalike/design/Solver.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace abalike
{

/// A castle part the generator builds with: a sandbox level of levels/parts/ (tools/levelgen's prefabs), standing on
/// flat ground at y = 0 around x = 0.
struct GeneratorPart
{
    std::string name; ///< the file's stem: "tower-3"
    LevelDef shape;   ///< its blocks and pigs
};

/// Every part of a folder (levels/parts), sorted by name. Throws LevelLoadError naming a part that does not load.
std::vector<GeneratorPart> loadGeneratorParts(const std::string& folder, const Catalog& catalog);

/// The kinds of level the generator makes, each from the parts that suit it.
enum class GeneratedKind
{
    Towers,   ///< two or three towers closer than they are tall: each can fall onto the next
    Castle,   ///< a keep or a fortress, a gate or a cage before it
    Cages,    ///< a row of cages and frames
    Pyramid,  ///< pyramids of boxes shielding frames
    Bridge,   ///< a plank on two stone columns, pigs on and under it
    Hill,     ///< a structure on a hill of terrain
    Island,   ///< a structure on a raised island, a gap before it
    TntStore, ///< frames and towers round a TNT crate
};

/// "towers", "castle", "cages", "pyramid", "bridge", "hill", "island", "tnt store".
const char* generatedKindName(GeneratedKind kind);
/// Every kind, in the order above.
const std::vector<GeneratedKind>& generatedKinds();

/// What to generate. The same options and parts give the same level, to the byte, whatever the thread count.
struct GeneratorOptions
{
    std::uint64_t seed = 1;
    /// The share of the model player's tries that should lose, 0 (every try wins) to 1 (almost none); a level is kept
    /// when its measured share is within kLossTolerance of it.
    double lossShare = 0.5;
    std::vector<std::string> birds; ///< empty: chosen for the structure's materials, as many as the loss share needs
    std::string world = "earth";    ///< earth, moon, mars, titan or jupiter: gravity, air and look together
    int maxAttempts = 24;           ///< layouts and bird counts tried before giving up
    std::size_t playerRuns = 40;    ///< the model player's tries per measure
    int threads = 0;                ///< 0: every hardware thread
    /// Set and true: the generation stops at its next check (each rest test, solver shot and model-player run) and
    /// returns with `stopped`; how the endless mode's worker leaves when the game quits. Never changes a result.
    const std::atomic<bool>* stop = nullptr;
    /// Set: the thread count for each measure is read from it instead of `threads` (the endless mode gives a waiting
    /// player every core). Never changes a result.
    const std::atomic<int>* threadsNow = nullptr;

    static constexpr double kLossTolerance = 0.15;
    static constexpr int kMaxBodies = 30;
    static constexpr int kMaxBirds = 6;
};

/// Why an attempt was thrown away, as `bench generate` counts them.
enum class Rejection
{
    Fell,       ///< it does not stand (the rest test)
    Unwinnable, ///< the solver does not win it
    TooEasy,    ///< the model player loses less often than asked
    TooHard,    ///< ... or more often
};

/// "fell", "unwinnable", "too easy", "too hard".
const char* rejectionName(Rejection rejection);

/// A verified level, or the reasons none was found.
struct GeneratedLevel
{
    bool ok = false;
    std::uint64_t seed = 0; ///< GeneratorOptions::seed: the title's number
    LevelDef level;
    GeneratedKind kind = GeneratedKind::Towers;
    int attempts = 0;
    std::vector<Rejection> rejected; ///< one per thrown-away attempt, in order
    Solution solution;               ///< the solver's win
    PlayerDifficulty player;         ///< the model player's measure
    double lossShare = 0.0;          ///< 1 - the model player's win share
    double seconds = 0.0;
    bool stopped = false; ///< GeneratorOptions::stop was set before a level passed
};

/// Generates one level and verifies it before returning it: it stands (checkRest), the solver wins it, and the model
/// player's loss share is within kLossTolerance of the asked one. Tries layouts (and, with automatic birds, bird
/// counts) until one passes or maxAttempts is spent (or the stop flag is set); ok is false then. Throws
/// std::invalid_argument for an unknown world or bird, or an empty part list.
GeneratedLevel generateLevel(const std::vector<GeneratorPart>& parts, const GeneratorOptions& options,
                             const Catalog& catalog = Catalog::builtin());

} // namespace abalike

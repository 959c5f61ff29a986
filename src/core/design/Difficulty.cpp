#include "design/ParallelFor.hpp"

#include <abalike/design/Difficulty.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/util/SplitMix64.hpp>

#include <chrono>
#include <random>

namespace abalike
{

namespace
{
constexpr double kMinAngleDeg = 0.0;
constexpr double kMaxAngleDeg = 90.0;

/// Uniform in [lo, hi] from the raw generator: std::uniform_real_distribution is not the same on every library.
double uniform(std::mt19937_64& random, double lo, double hi)
{
    return lo + (hi - lo) * static_cast<double>(random() >> 11) * 0x1.0p-53;
}
} // namespace

Difficulty measureDifficulty(const LevelDef& level, std::size_t samples, std::uint64_t seed, const Catalog& catalog,
                             int threads, const ProgressCallback& progress)
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> topSpeed;
    const Catalog levelTable = levelCatalog(level, catalog); // with the level's custom bird
    for (const std::string& name : level.birds)
        topSpeed.push_back(maxLaunchSpeed(level, *levelTable.findBird(name), levelTable));
    std::vector<ShotOutcome> outcomes(samples);
    std::size_t done = 0;
    parallelFor(
        samples, workerCount(threads),
        [&](std::size_t i)
        {
            std::mt19937_64 random(SplitMix64::mix(seed ^ SplitMix64::mix(i)));
            std::vector<ScriptedShot> shots;
            for (const double top : topSpeed)
            {
                const double angle = uniform(random, kMinAngleDeg, kMaxAngleDeg);
                shots.push_back({angle, uniform(random, 0.0, top), std::nullopt});
            }
            outcomes[i] = playShots(level, shots, catalog);
        },
        [&](std::size_t)
        {
            if (progress)
                progress(++done, samples);
        });
    Difficulty out;
    out.samples = samples;
    for (const ShotOutcome& o : outcomes)
    {
        out.wins += o.won ? 1 : 0;
        out.pigShare += 1.0 - static_cast<double>(o.pigsRemaining) / static_cast<double>(level.pigs.size());
    }
    if (samples > 0)
    {
        out.winShare = static_cast<double>(out.wins) / static_cast<double>(samples);
        out.pigShare /= static_cast<double>(samples);
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace abalike

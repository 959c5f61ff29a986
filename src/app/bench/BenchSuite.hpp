#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// Options shared by every `abalike bench NAME` suite.
struct BenchOptions
{
    std::string outDir = "bench-out"; ///< where the suite writes its .csv/.md/.png files
    bool quick = false;               ///< fewer repetitions (used by ctest smoke runs)
    std::vector<std::string> scenes;  ///< `bench frames --scene`: only these (level ids, lesson ids, stress scenes)
    std::size_t seeds = 0;            ///< `bench generate --seeds N`: levels to generate (0: 20, 2 with --quick)
    bool noCopies = false;            ///< `bench difficulty --no-copies`: search trials replayed, not copied
};

// Each suite prints its table, writes its files into outDir and returns the exit code.
int runAccuracyBench(const BenchOptions& options);   ///< integration error against run time (flight issue)
int runStabilityBench(const BenchOptions& options);  ///< stiff and extreme cases (flight issue)
int runReferenceBench(const BenchOptions& options);  ///< predicted vs actual first contact on the reference shots
int runPerfBench(const BenchOptions& options);       ///< world step times and headless speed (world issue)
int runSoakBench(const BenchOptions& options);       ///< 10 000 shots, resident memory start to end (reliability)
int runFramesBench(const BenchOptions& options);     ///< the game loop's frame times under the display (game issue)
int runFeelBench(const BenchOptions& options);       ///< break-through, toppling and the pace of turns (core loop)
int runGenerateBench(const BenchOptions& options);   ///< time per verified generated level, rejections, variety
int runDifficultyBench(const BenchOptions& options); ///< how long check --solve takes per campaign level

} // namespace abalike::app

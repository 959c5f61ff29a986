#include "bench/BenchSuite.hpp"
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"

#include <filesystem>
#include <memory>

namespace abalike::app
{

namespace
{

struct BenchArgs
{
    BenchOptions options;
};

/// Creates the output folder, or says clearly why it cannot.
void prepareOutDir(const std::string& dir)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw UsageError("--out: cannot create folder " + dir + (ec ? ": " + ec.message() : ""));
}

} // namespace

CommandRunner addBenchCommand(CLI::App& app)
{
    auto args = std::make_shared<BenchArgs>();
    auto chosen = std::make_shared<int (*)(const BenchOptions&)>(nullptr);
    CLI::App* cmd = app.add_subcommand("bench", "Measure speed and accuracy; writes CSV and Markdown reports");
    cmd->require_subcommand(1);
    const struct
    {
        const char* name;
        const char* help;
        int (*run)(const BenchOptions&);
    } suites[] = {
        {"accuracy", "integration error against run time for every stepper", runAccuracyBench},
        {"stability", "stiff and extreme flights: what plain RK4 does and what the guard does", runStabilityBench},
        {"reference", "predicted vs actual first contact on the reference shots", runReferenceBench},
        {"perf", "world step times per level, overhead against raw Box2D, headless speed", runPerfBench},
        {"soak", "10 000 random headless shots across the campaign; fails if resident memory grows > 5%", runSoakBench},
        {"frames",
         "frame times and load times of the game loop under the current display: every level and lesson, 1280x720 "
         "and 1920x1080, every overlay on",
         runFramesBench},
        {"feel", "break-through, toppling defeats and the pace of turns over the campaign", runFeelBench},
        {"generate",
         "time per verified generated level, attempts rejected by reason, kinds, layout distance and toppling",
         runGenerateBench},
        {"difficulty",
         "how long check --solve takes per campaign level (rest test, solver, model player, star thresholds)",
         runDifficultyBench},
    };
    for (const auto& suite : suites)
    {
        CLI::App* sub = cmd->add_subcommand(suite.name, suite.help);
        sub->add_option("--out", args->options.outDir, "output folder (default bench-out)");
        sub->add_flag("--quick", args->options.quick, "fewer repetitions, for smoke tests");
        if (std::string_view(suite.name) == "difficulty")
        {
            sub->add_option("--scene", args->options.scenes, "only this campaign level (1-3); repeat for more");
            sub->add_flag("--no-copies", args->options.noCopies,
                          "play every search trial from the level's start, not on a copy of the process (for a "
                          "ratio)");
        }
        if (std::string_view(suite.name) == "frames")
            sub->add_option("--scene", args->options.scenes,
                            "only this scene: a level id (1-3), a lesson id (lesson-angle) or a stress scene "
                            "(wall-20x50-mixed); repeat for more");
        if (std::string_view(suite.name) == "generate")
            sub->add_option("--seeds", args->options.seeds, "levels to generate, seeds 1 to N (default 20)");
        sub->callback([chosen, run = suite.run] { *chosen = run; });
    }
    return [args, chosen]
    {
        prepareOutDir(args->options.outDir);
        return (*chosen)(args->options);
    };
}

} // namespace abalike::app

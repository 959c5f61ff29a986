#include "cli/Commands.hpp"
#include "cli/ProgressBar.hpp"
#include "cli/SolutionJson.hpp"
#include "cli/UsageError.hpp"

#include <abalike/design/Difficulty.hpp>
#include <abalike/design/ModelPlayer.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/SafeText.hpp>

#include <iomanip>
#include <iostream>
#include <memory>

namespace abalike::app
{

namespace
{

struct SolveArgs
{
    std::string level;
    bool json = false;
    int threads = 0;
    bool noAbilities = false;
    std::size_t difficultySamples = 0;
    std::uint64_t seed = 1;
    std::size_t playerRuns = 40;
};

int runSolve(const SolveArgs& a)
{
    if (a.threads < 0 || a.threads > 256)
        throw UsageError("--threads: expected 0 (all cores) to 256, got " + std::to_string(a.threads));
    if (a.difficultySamples > 1000000)
        throw UsageError("--difficulty: expected at most 1000000 samples, got " + std::to_string(a.difficultySamples));
    const LevelDef level = loadLevel(a.level, Catalog::builtin());

    SolverOptions options;
    options.threads = a.threads;
    options.tryAbilities = !a.noAbilities;
    ProgressBar bar("solving " + level.id);
    options.progress = [&bar](std::size_t done, std::size_t total)
    {
        bar.update(done, total);
    };
    const Solution solution = solveLevel(level, Catalog::builtin(), options);
    bar.finish();

    std::optional<Difficulty> difficulty;
    if (a.difficultySamples > 0)
    {
        ProgressBar randomBar("random play " + level.id);
        difficulty =
            measureDifficulty(level, a.difficultySamples, a.seed, Catalog::builtin(), a.threads,
                              [&randomBar](std::size_t done, std::size_t total) { randomBar.update(done, total); });
    }

    std::optional<PlayerDifficulty> player;
    if (a.playerRuns > 0 && solution.pigsFallingAlone.empty())
    {
        ProgressBar playerBar("model player " + level.id);
        ModelPlayerOptions playerOptions;
        playerOptions.runs = a.playerRuns;
        playerOptions.seed = a.seed;
        playerOptions.threads = a.threads;
        playerOptions.progress = [&playerBar](std::size_t done, std::size_t total)
        {
            playerBar.update(done, total);
        };
        player = measurePlayerDifficulty(level, Catalog::builtin(), playerOptions);
        playerBar.finish();
    }

    if (a.json)
    {
        nlohmann::ordered_json out = solutionToJson(level, solution);
        if (player)
            out["player"] = playerDifficultyJson(*player);
        if (difficulty)
            out["difficulty"] = {{"samples", difficulty->samples},
                                 {"wins", difficulty->wins},
                                 {"win_share", difficulty->winShare},
                                 {"pig_share", difficulty->pigShare}};
        std::cout << out.dump() << '\n';
        return 0;
    }
    std::cout << level.id << " \"" << level.title << "\": " << (solution.outcome.won ? "won" : "not solved")
              << ", score " << solution.outcome.score << ", " << solution.outcome.stars << " star(s), "
              << solution.shots.size() << " shot(s), " << solution.simulations << " simulations in " << std::fixed
              << std::setprecision(1) << solution.seconds << " s\n";
    if (!solution.pigsFallingAlone.empty())
    {
        std::cout << "  the level does not stand: pig(s)";
        for (const int pig : solution.pigsFallingAlone)
            std::cout << ' ' << pig;
        std::cout << " fall or take damage before any shot, so nothing was searched (abalike check says why)\n";
        return 0;
    }
    std::cout << "  replay: abalike simulate " << escapeForTerminal(a.level) << ' ' << shotArguments(solution.shots)
              << '\n';
    if (!solution.survivingPigs.empty())
    {
        std::cout << "  pigs left standing:";
        for (const int pig : solution.survivingPigs)
            std::cout << " pig " << pig << " (" << level.pigs[static_cast<std::size_t>(pig)].type
                      << " at x = " << level.pigs[static_cast<std::size_t>(pig)].x << ")";
        std::cout << '\n';
    }
    if (player)
        std::cout << "  " << playerDifficultyText(*player) << '\n';
    if (difficulty)
        std::cout << "  random play: " << difficulty->wins << " of " << difficulty->samples << " random sequences won ("
                  << std::setprecision(1) << 100.0 * difficulty->winShare << "%), " << std::setprecision(0)
                  << 100.0 * difficulty->pigShare << "% of pigs defeated on average\n";
    return 0;
}

} // namespace

CommandRunner addSolveCommand(CLI::App& app)
{
    auto args = std::make_shared<SolveArgs>();
    CLI::App* cmd = app.add_subcommand("solve", "Search for shots that win a level (headless, all cores)");
    cmd->add_option("level", args->level, "level JSON file")->required();
    cmd->add_flag("--json", args->json, "print one JSON object");
    cmd->add_option("--threads", args->threads, "worker threads (default 0: every core)");
    cmd->add_flag("--no-abilities", args->noAbilities, "do not try the birds' abilities");
    cmd->add_option("--difficulty", args->difficultySamples,
                    "also play N random full shot sequences and report the share that wins");
    cmd->add_option("--seed", args->seed, "seed of the random sequences and the model player's aim (default 1)");
    cmd->add_option("--player-runs", args->playerRuns,
                    "plays of the model player, whose win rate is the level's difficulty (default 40; 0: none)");
    return [args]
    {
        return runSolve(*args);
    };
}

} // namespace abalike::app

#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/SafeText.hpp>

#include <iostream>
#include <map>
#include <string>

int main(int argc, char** argv)
{
    using namespace abalike::app;
    CLI::App app{"Angry Birds Alike: a slingshot physics game and physics teaching tool", "abalike"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "abalike " ABALIKE_VERSION);
    std::map<std::string, CommandRunner> commands;
    commands["predict"] = addPredictCommand(app);
    commands["simulate"] = addSimulateCommand(app);
    commands["play"] = addPlayCommand(app);
    commands["edit"] = addEditCommand(app);
    commands["bench"] = addBenchCommand(app);
    commands["check"] = addCheckCommand(app);
    commands["solve"] = addSolveCommand(app);
    commands["walkthrough"] = addWalkthroughCommand(app);
    commands["chart"] = addChartCommand(app);
    commands["fmt"] = addFmtCommand(app);
    commands["import"] = addImportCommand(app);
    commands["generate"] = addGenerateCommand(app);

    // CLI11 would only say "a subcommand is required" for `abalike fly`; name the word it did not know.
    if (argc > 1 && argv[1][0] != '-' && commands.count(argv[1]) == 0)
    {
        std::string known;
        for (const auto& entry : commands)
            known += (known.empty() ? "" : ", ") + entry.first;
        std::cerr << "abalike: error: unknown command \"" << abalike::escapeForTerminal(argv[1])
                  << "\" (expected one of: " << known << ")\n";
        return kUsageExitCode;
    }

    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::CallForHelp&)
    {
        std::cout << app.help();
        return 0;
    }
    catch (const CLI::CallForAllHelp&)
    {
        std::cout << app.help("", CLI::AppFormatMode::All);
        return 0;
    }
    catch (const CLI::CallForVersion& e)
    {
        std::cout << e.what() << '\n';
        return 0;
    }
    catch (const CLI::ParseError& e)
    {
        std::cerr << "abalike: error: " << abalike::escapeForTerminal(e.what()) << " (see abalike --help)\n";
        return kUsageExitCode;
    }

    try
    {
        for (const auto& [name, run] : commands)
            if (app.got_subcommand(name))
                return run();
    }
    catch (const UsageError& e)
    {
        // Messages may quote file names and arguments: escape what would act on a terminal.
        std::cerr << "abalike: error: " << abalike::escapeForTerminal(e.what()) << '\n';
        return kUsageExitCode;
    }
    catch (const abalike::LevelLoadError& e)
    {
        // Every problem found, one per line, in the FILE:LINE:COL form editors jump to.
        for (const auto& issue : e.issues())
            std::cerr << issue.format() << '\n';
        return kUsageExitCode;
    }
    catch (const std::exception& e)
    {
        std::cerr << "abalike: error: " << abalike::escapeForTerminal(e.what()) << '\n';
        return 1;
    }
    return 0;
}

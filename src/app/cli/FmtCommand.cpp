// `abalike fmt FILE... [--check]`: rewrites level files in the layout the editor saves, so hand edits and editor
// saves agree and diffs stay one line per moved body.
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>

namespace abalike::app
{

namespace
{

struct FmtArgs
{
    std::vector<std::string> files;
    bool check = false;
};

int runFmt(const FmtArgs& a)
{
    int exitCode = 0;
    for (const std::string& file : a.files)
    {
        std::ifstream in(file, std::ios::binary);
        if (!in)
        {
            std::cerr << escapeForTerminal(file) << ": error: cannot read the file\n";
            exitCode = kUsageExitCode;
            continue;
        }
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (isCampaignManifest(file))
        {
            std::cerr << escapeForTerminal(file) << ": skipped: a campaign manifest, not a level\n";
            continue;
        }
        std::string formatted;
        try
        {
            // Geometry problems (an overlap, a pig out of reach) do not stop formatting: the file still reads.
            formatted = writeLevelJson(loadLevelForEditing(file, Catalog::builtin()).level, schemaReferenceOf(text));
        }
        catch (const LevelLoadError& e)
        {
            for (const LevelIssue& issue : e.issues())
                std::cerr << escapeForTerminal(issue.format()) << '\n';
            exitCode = kUsageExitCode;
            continue;
        }
        if (formatted == text)
            continue;
        if (a.check)
        {
            std::cout << "would reformat " << escapeForTerminal(file) << '\n';
            exitCode = std::max(exitCode, 1);
            continue;
        }
        writeFileAtomically(file, formatted);
        std::cout << "formatted " << escapeForTerminal(file) << '\n';
    }
    return exitCode;
}

} // namespace

CommandRunner addFmtCommand(CLI::App& app)
{
    auto args = std::make_shared<FmtArgs>();
    CLI::App* cmd = app.add_subcommand(
        "fmt", "Rewrite level files in the layout the editor saves (one body per line, shortest exact numbers)");
    cmd->add_option("files", args->files, "level JSON files")->required();
    cmd->add_flag("--check", args->check, "change nothing; exit 1 if a file would change");
    return [args]
    {
        return runFmt(*args);
    };
}

} // namespace abalike::app

// `abalike import FILE.xml -o LEVEL.json`: converts a Science Birds level (the game's and the AIBIRDS competitions'
// XML) into a level of ours, reporting each change the conversion made at its place in the XML file.
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/level/ScienceBirds.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/world/Catalog.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>

namespace abalike::app
{

namespace
{

struct ImportArgs
{
    std::string input;
    std::string output;
    std::string id;
    std::string title;
    bool force = false;
    bool sandbox = false;
};

/// "FILE:LINE:COL: warning: /pointer: message", as compilers write them; the pointer (of the level written) only
/// where the message concerns one of its bodies, the place only where the XML file has one.
std::string formatIssue(const LevelIssue& issue, const char* kind)
{
    std::string text = issue.file;
    if (issue.line > 0)
        text.append(":").append(std::to_string(issue.line)).append(":").append(std::to_string(issue.column));
    text.append(": ").append(kind).append(": ");
    if (!issue.pointer.empty())
        text.append(issue.pointer).append(": ");
    return text.append(issue.message);
}

std::string counted(std::size_t n, const std::string& one, const std::string& many)
{
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

int runImport(const ImportArgs& a)
{
    std::ifstream in(a.input, std::ios::binary);
    if (!in)
        throw UsageError("cannot read \"" + a.input + "\"");
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::filesystem::path output(a.output);
    if (std::filesystem::exists(output) && !a.force)
        throw UsageError("\"" + a.output + "\" exists (use --force to replace it)");

    ScienceBirdsLevel imported;
    try
    {
        imported = importScienceBirds(bytes, a.input, Catalog::builtin(), ScienceBirdsOptions{a.sandbox});
    }
    catch (const LevelLoadError& e)
    {
        for (const LevelIssue& issue : e.issues())
            std::cerr << escapeForTerminal(formatIssue(issue, "error")) << '\n';
        return kUsageExitCode;
    }
    if (!a.id.empty())
        imported.level.id = a.id;
    if (!a.title.empty())
        imported.level.title = a.title;
    const std::vector<LevelIssue> fields = checkLevelFields(imported.level, Catalog::builtin());
    if (!fields.empty())
        throw LevelLoadError(fields); // a bad --id or --title
    for (const LevelIssue& warning : imported.warnings)
        std::cerr << escapeForTerminal(formatIssue(warning, "warning")) << '\n';

    const std::filesystem::path schema = std::filesystem::path(levelsDirectory()) / "schema" / "level.schema.json";
    writeFileAtomically(output, writeLevelJson(imported.level, schemaReferenceToWrite(output, schema)));
    const LevelDef& level = imported.level;
    std::cout << "imported " << escapeForTerminal(a.input) << " -> " << escapeForTerminal(a.output) << ": "
              << counted(level.blocks.size(), "block", "blocks") << ", " << counted(level.pigs.size(), "pig", "pigs")
              << ", " << counted(level.terrain.size(), "terrain piece", "terrain pieces") << ", "
              << counted(level.birds.size(), "bird", "birds") << "; "
              << counted(imported.warnings.size(), "warning", "warnings") << '\n';
    return 0;
}

} // namespace

CommandRunner addImportCommand(CLI::App& app)
{
    auto args = std::make_shared<ImportArgs>();
    CLI::App* cmd = app.add_subcommand(
        "import", "Convert a Science Birds level (XML, as the AIBIRDS competitions use) into a level file; each change "
                  "the conversion makes is reported at its line of the XML file");
    cmd->add_option("file", args->input, "Science Birds level (.xml; UTF-8 or UTF-16)")->required();
    cmd->add_option("-o,--output", args->output, "level JSON file to write")->required();
    cmd->add_option("--id", args->id, "the level's id (default: from the file name)");
    cmd->add_option("--title", args->title, "the level's title (default: \"Science Birds: ID\")");
    cmd->add_flag("--force", args->force, "replace the output file if it exists");
    cmd->add_flag("--sandbox", args->sandbox,
                  "write a sandbox scene (it may have no pig): a structure to open in the editor, never in a pack");
    return [args]
    {
        return runImport(*args);
    };
}

} // namespace abalike::app

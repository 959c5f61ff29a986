#include "FuzzInput.hpp"
#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using namespace abalike::app;

/// Predictions longer than this are parsed but not run: the CLI allows 2 million steps, seconds per input.
constexpr double kMaxRunSteps = 5000.0;
constexpr std::size_t kMaxInputBytes = 4096;

/// Runs a parser on text; bad input must come back as UsageError and nothing else.
template <class F>
void expectUsageErrorOrValue(F parse)
{
    try
    {
        parse();
    }
    catch (const UsageError&)
    {
    }
}

/// The value given for an option, or fallback when it was not given.
std::string optionText(CLI::App& command, const std::string& name, const std::string& fallback)
{
    const CLI::Option* option = command.get_option(name);
    return option->count() == 0 ? fallback : option->results().back();
}

/// Whether `abalike predict` with these options would stay short enough to run inside the fuzzer.
bool shortPrediction(CLI::App& predict)
{
    try
    {
        const double dt = parseFinite(optionText(predict, "--dt", "0.0166666"), "--dt");
        const double end =
            parseFinite(optionText(predict, "--until-t", optionText(predict, "--max-t", "60")), "--until-t");
        return !(end / dt > kMaxRunSteps);
    }
    catch (const UsageError&)
    {
        return true; // the command rejects it before integrating anything
    }
}

/// Runs a command (predict, walkthrough) with its output captured; a successful run must print only finite numbers.
/// A walkthrough without a closed form prints "exact":null by contract, which is no such number.
void runPredict(const CommandRunner& run, bool exactMayBeNull = false)
{
    std::ostringstream out;
    std::streambuf* const saved = std::cout.rdbuf(out.rdbuf());
    int code = 0;
    try
    {
        code = run();
    }
    catch (const UsageError&)
    {
        code = kUsageExitCode;
    }
    catch (...)
    {
        std::cout.rdbuf(saved);
        throw;
    }
    std::cout.rdbuf(saved);
    std::string text = out.str();
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    if (const auto at = text.find("\"exact\":null"); exactMayBeNull && at != std::string::npos)
        text.erase(at, 12);
    // nlohmann writes NaN and infinity as null; the text mode prints nan and inf.
    if (code == 0 && (text.find("null") != std::string::npos || text.find("nan") != std::string::npos ||
                      text.find("inf") != std::string::npos))
        abalike::fuzz::fail("a command printed a non-finite number instead of refusing its input");
}

} // namespace

/// The command line: each line of the input is one argument. The argument parsers must turn every string into a
/// value or a UsageError; CLI11 with the real predict and simulate option sets must parse or give a ParseError;
/// short predictions are run and must print finite numbers only.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > kMaxInputBytes)
        return 0;
    std::vector<std::string> args{"abalike"};
    std::istringstream lines(std::string(abalike::fuzz::asText(data, size)));
    for (std::string line; std::getline(lines, line);)
        args.push_back(line);

    for (const std::string& arg : args)
    {
        expectUsageErrorOrValue([&] { parseFinite(arg, "--speed"); });
        expectUsageErrorOrValue([&] { parsePair(arg, "--wind"); });
        expectUsageErrorOrValue([&] { parseShot(arg); });
        expectUsageErrorOrValue([&] { parseSize(arg); });
    }

    CLI::App app{"abalike under the fuzzer", "abalike"};
    app.require_subcommand(1);
    const CommandRunner predict = addPredictCommand(app);
    // Kept although never run: each runner owns the variables its options write into while parsing.
    const CommandRunner simulate = addSimulateCommand(app);
    const CommandRunner walkthrough = addWalkthroughCommand(app); // one RK4 step: always short enough to run
    std::vector<char*> argv;
    for (std::string& arg : args)
        argv.push_back(arg.data());
    try
    {
        app.parse(static_cast<int>(argv.size()), argv.data());
    }
    catch (const CLI::ParseError&)
    {
        return 0;
    }
    if (CLI::App* cmd = app.get_subcommand("predict"); cmd->parsed() && shortPrediction(*cmd))
        runPredict(predict);
    if (app.get_subcommand("walkthrough")->parsed())
        runPredict(walkthrough, true); // same rule: finite numbers or a UsageError
    if (CLI::App* cmd = app.get_subcommand("simulate"); cmd->parsed())
        // Only the shots: running simulate would read whatever file the input names.
        for (const std::string& shot : cmd->get_option("--shot")->results())
            expectUsageErrorOrValue([&] { parseShot(shot); });
    return 0;
}

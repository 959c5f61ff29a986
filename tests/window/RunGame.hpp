#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace abalike::test
{

/// The window every flow runs in unless it asks for another.
inline const std::string kWindowSize = " --size 1280x720";

/// A folder of its own for one test, removed when the test ends.
class ScratchDir
{
public:
    explicit ScratchDir(const std::string& name)
        : m_path(std::filesystem::temp_directory_path() / ("abalike-window-" + name + "-" + std::to_string(::getpid())))
    {
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~ScratchDir() { std::filesystem::remove_all(m_path); }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    std::string file(const std::string& name) const { return (m_path / name).string(); }
    /// Writes a file in the folder and returns its path.
    std::string write(const std::string& name, const std::string& text) const
    {
        std::ofstream(m_path / name) << text;
        return file(name);
    }

private:
    std::filesystem::path m_path;
};

/// What a game run did: its exit code, what it printed on stderr, and its trace (one JSON object per line).
struct GameRun
{
    int exitCode = -1;
    std::string err;
    std::vector<nlohmann::json> trace;

    /// The values of `key` in trace events named `event`, in order.
    std::vector<std::string> values(const std::string& event, const std::string& key) const
    {
        std::vector<std::string> out;
        for (const nlohmann::json& line : trace)
            if (line.value("event", "") == event && line.contains(key))
                out.push_back(line[key].is_string() ? line[key].get<std::string>() : line[key].dump());
        return out;
    }
    /// The screens on the stack when the run ended, bottom first.
    std::vector<std::string> finalScreens() const
    {
        for (auto it = trace.rbegin(); it != trace.rend(); ++it)
            if (it->value("event", "") == "exit")
                return (*it)["screens"].get<std::vector<std::string>>();
        return {};
    }
};

/// Runs `abalike ARGS --trace FILE` with the player's files in dataDir; the display comes from the environment
/// (ctest starts this test binary under tests/window/xvfb.sh).
inline GameRun runGame(const std::string& args, const std::filesystem::path& dataDir)
{
    static int counter = 0;
    const std::string stem = (dataDir.parent_path() / ("run-" + std::to_string(counter++))).string();
    const std::string tracePath = stem + ".trace";
    const std::string errPath = stem + ".err";
    const std::string command = "ABALIKE_DATA_DIR='" + dataDir.string() + "' '" + ABALIKE_EXECUTABLE + "' " + args +
                                " --trace '" + tracePath + "' >/dev/null 2>'" + errPath + "'";
    GameRun run;
    const int status = std::system(command.c_str());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::stringstream err;
    err << std::ifstream(errPath).rdbuf();
    run.err = err.str();
    std::ifstream trace(tracePath);
    for (std::string line; std::getline(trace, line);)
        run.trace.push_back(nlohmann::json::parse(line));
    std::filesystem::remove(tracePath);
    std::filesystem::remove(errPath);
    return run;
}

/// The source tree's copy of a file, e.g. sourceFile("levels/1-1-first-flight.json").
inline std::string sourceFile(const std::string& relative)
{
    return std::string(ABALIKE_SOURCE_DIR) + "/" + relative;
}

} // namespace abalike::test

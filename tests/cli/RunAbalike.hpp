#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace abalike::test
{

/// What a run of the abalike executable produced.
struct RunResult
{
    int exitCode = -1;
    std::string out;
    std::string err;
};

/// Runs a shell command line and captures stdout, stderr and the exit code.
inline RunResult runCommand(const std::string& commandLine)
{
    static int counter = 0;
    const auto errFile = std::filesystem::temp_directory_path() /
                         ("abalike-cli-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".err");
    const std::string command = commandLine + " 2>" + errFile.string();
    RunResult result;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr)
        return result;
    std::array<char, 65536> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        result.out.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::ifstream err(errFile);
    std::stringstream text;
    text << err.rdbuf();
    result.err = text.str();
    std::filesystem::remove(errFile);
    return result;
}

/// Runs `abalike ARGS` through the shell (args are passed as written) and captures stdout, stderr and the exit code.
inline RunResult runAbalike(const std::string& args)
{
    return runCommand(std::string(ABALIKE_EXECUTABLE) + " " + args);
}

/// Path of a file in the source tree, e.g. sourcePath("levels/campaign.json").
inline std::string sourcePath(const std::string& relative)
{
    return std::string(ABALIKE_SOURCE_DIR) + "/" + relative;
}

} // namespace abalike::test

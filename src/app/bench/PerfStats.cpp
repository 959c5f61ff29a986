#include "bench/PerfParts.hpp"

#include <algorithm>
#include <fstream>
#include <numeric>
#include <sstream>
#include <thread>

namespace abalike::app
{

StepStats statsOf(std::vector<double> secondsPerStep)
{
    StepStats stats;
    stats.count = secondsPerStep.size();
    if (secondsPerStep.empty())
        return stats;
    std::sort(secondsPerStep.begin(), secondsPerStep.end());
    const auto at = [&](double q)
    {
        const auto i = static_cast<std::size_t>(q * static_cast<double>(secondsPerStep.size() - 1) + 0.5);
        return 1e6 * secondsPerStep[i];
    };
    stats.medianUs = at(0.5);
    stats.p95Us = at(0.95);
    stats.totalS = std::accumulate(secondsPerStep.begin(), secondsPerStep.end(), 0.0);
    stats.meanUs = 1e6 * stats.totalS / static_cast<double>(secondsPerStep.size());
    return stats;
}

std::string machineDescription()
{
    std::string cpu = "unknown CPU";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0)
        {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    std::ostringstream out;
    out << cpu << ", " << std::thread::hardware_concurrency() << " hardware threads, ";
#if defined(__clang__)
    out << "clang " << __clang_version__;
#elif defined(__GNUC__)
    out << "GCC " << __VERSION__;
#endif
#if defined(NDEBUG)
    out << ", optimised build";
#else
    out << ", debug build (assertions on: timings are not representative)";
#endif
    return out.str();
}

} // namespace abalike::app

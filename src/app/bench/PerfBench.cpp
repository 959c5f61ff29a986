#include "bench/BenchSuite.hpp"

#include <iostream>

namespace abalike::app
{

int runPerfBench(const BenchOptions& /*options*/)
{
    std::cerr << "abalike: error: bench perf is not implemented yet\n";
    return 1;
}

} // namespace abalike::app

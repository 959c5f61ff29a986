#include "bench/BenchSuite.hpp"

#include <iostream>

namespace abalike::app
{

int runStabilityBench(const BenchOptions& /*options*/)
{
    std::cerr << "abalike: error: bench stability is not implemented yet\n";
    return 1;
}

} // namespace abalike::app

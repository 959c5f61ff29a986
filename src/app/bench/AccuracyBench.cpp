#include "bench/BenchSuite.hpp"

#include <iostream>

namespace abalike::app
{

int runAccuracyBench(const BenchOptions& /*options*/)
{
    std::cerr << "abalike: error: bench accuracy is not implemented yet\n";
    return 1;
}

} // namespace abalike::app

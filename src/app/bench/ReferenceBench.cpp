#include "bench/BenchSuite.hpp"

#include <iostream>

namespace abalike::app
{

int runReferenceBench(const BenchOptions& /*options*/)
{
    std::cerr << "abalike: error: bench reference is not implemented yet\n";
    return 1;
}

} // namespace abalike::app

#include <abalike/design/GeneratorLayouts.hpp>

#include <cmath>

namespace abalike
{

GeneratorRng::GeneratorRng(std::uint64_t seed, std::uint64_t stream)
    : m_state(seed * 0x9E3779B97F4A7C15ull ^ (stream + 1) * 0xD1B54A32D192ED03ull)
{
}

std::uint64_t GeneratorRng::next()
{
    // SplitMix64 (Steele, Lea and Flood 2014): a 64-bit counter through a fixed mixing function.
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double GeneratorRng::metres(double lo, double hi)
{
    const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53; // [0, 1), exact on every platform
    return std::round((lo + unit * (hi - lo)) * 100.0) / 100.0;
}

std::size_t GeneratorRng::index(std::size_t n)
{
    return static_cast<std::size_t>(next() % n);
}

} // namespace abalike

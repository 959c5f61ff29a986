#pragma once

#include <cstdint>

namespace abalike
{

/// splitmix64 (Steele, Lea and Flood, 2014): a tiny generator whose sequence is the same on every platform and
/// standard library (std's distributions are not), for the model player's aim, the difficulty's samples and the
/// renderer's decoration.
class SplitMix64
{
public:
    explicit SplitMix64(std::uint64_t state) : m_state(state) {}

    std::uint64_t next()
    {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    /// Uniform in the open interval (0, 1), 53 bits.
    double uniform() { return (static_cast<double>(next() >> 11) + 0.5) / 9007199254740992.0; }

    /// The first number of a generator seeded with x: spreads a seed into well-mixed bits.
    static std::uint64_t mix(std::uint64_t x) { return SplitMix64(x).next(); }

private:
    std::uint64_t m_state;
};

} // namespace abalike

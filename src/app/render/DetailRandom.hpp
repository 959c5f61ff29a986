#pragma once

#include <cstdint>

namespace abalike::app
{

/// A tiny seeded generator (splitmix64) for decoration: the same entity gets the same grain, speckles and
/// cracks every frame, so nothing flickers.
class DetailRandom
{
public:
    explicit DetailRandom(std::uint64_t seed) : m_state(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}

    std::uint64_t next()
    {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    /// Uniform in [0, 1).
    float unit() { return static_cast<float>(next() >> 40) / static_cast<float>(1ull << 24); }
    /// Uniform in [lo, hi).
    float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [0, n).
    int below(int n) { return n > 0 ? static_cast<int>(next() % static_cast<std::uint64_t>(n)) : 0; }

private:
    std::uint64_t m_state;
};

} // namespace abalike::app

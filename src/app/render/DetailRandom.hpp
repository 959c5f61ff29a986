#pragma once

#include <abalike/util/SplitMix64.hpp>
#include <cstdint>

namespace abalike::app
{

/// A seeded generator (SplitMix64) for decoration: the same entity gets the same grain, speckles and
/// cracks every frame, so nothing flickers.
class DetailRandom
{
public:
    explicit DetailRandom(std::uint64_t seed) : m_random(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}

    std::uint64_t next() { return m_random.next(); }

    /// Uniform in [0, 1).
    float unit() { return static_cast<float>(next() >> 40) / static_cast<float>(1ull << 24); }
    /// Uniform in [lo, hi).
    float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [0, n).
    int below(int n) { return n > 0 ? static_cast<int>(next() % static_cast<std::uint64_t>(n)) : 0; }

private:
    SplitMix64 m_random;
};

} // namespace abalike::app

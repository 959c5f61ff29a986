#pragma once

#include <abalike/design/Generator.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// The generator's random source: SplitMix64 over (seed, stream). It gives the same numbers on every platform, which
/// the standard library's distributions do not promise, so a seed names one level everywhere.
class GeneratorRng
{
public:
    GeneratorRng(std::uint64_t seed, std::uint64_t stream);

    std::uint64_t next();
    /// In [lo, hi), rounded to whole centimetres so the level file reads well.
    double metres(double lo, double hi);
    /// In [0, n).
    std::size_t index(std::size_t n);
    /// True with probability one half.
    bool coin() { return (next() >> 63) != 0; }

private:
    std::uint64_t m_state;
};

/// Lays out a level of a kind the source draws (or `only` that kind): castle parts placed left to right from 20-30 m,
/// on the ground or on terrain, at most maxBodies blocks and pigs (at least 12 when the budget allows), at least one
/// pig. Returns the kind.
GeneratedKind layOut(LevelDef& level, const std::vector<GeneratorPart>& parts, GeneratorRng& rng,
                     const Catalog& catalog, std::optional<GeneratedKind> only = {},
                     int maxBodies = GeneratorOptions::kMaxBodies);

/// A structure of one kind for the editor's "Generate here": laid out within maxBodies and verified to stand on its
/// own (the rest test), trying the seed's next streams when one does not (at most 8). nullopt when none stands.
std::optional<LevelDef> generateStructure(const std::vector<GeneratorPart>& parts, GeneratedKind kind, int maxBodies,
                                          std::uint64_t seed, const Catalog& catalog);

/// Sets the level's gravity, air and look to a world's (earth, moon, mars, titan, jupiter; GravityPresets), its band
/// scaled with gravity so the arcs stay on screen (the campaign's Moon and Jupiter levels do the same) but never below
/// a third of Earth's, so a full pull still breaks wood. Earth keeps the format's defaults (still air). Throws
/// std::invalid_argument for another name.
void applyGeneratorWorld(LevelDef& level, const std::string& world);

/// How different two layouts are: 1 minus the Jaccard index of their occupancy grids, the 0.5 m cells whose centres
/// lie inside a block's bounding box or a pig's (on an edge, within a micrometre, counts), counted from each level's
/// leftmost body (a layout moved sideways is the same layout). 0: the same cells; 1: no cell in common.
double layoutDistance(const LevelDef& a, const LevelDef& b, const Catalog& catalog);

/// A hint for a level of this kind: what its structure invites, with no number to go stale.
std::string kindHint(GeneratedKind kind);

} // namespace abalike

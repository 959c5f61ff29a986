#pragma once

#include <abalike/design/GeneratorLayouts.hpp>
#include <abalike/level/LevelDef.hpp>

#include <string>
#include <vector>

namespace abalike
{

/// How the generator changes a castle part before it places it, so that a few parts make many layouts: stretched
/// sideways, mirrored, its wood turned to ice. The identity leaves the part as it is.
struct PartVariation
{
    /// Sideways scale about the part's middle: positions spread, floors, planks and cages widen, posts keep their
    /// width, so what rested on what still does.
    double stretch = 1.0;
    /// Left and right swapped (pigs, posts, roof triangles).
    bool mirror = false;
    /// Every wood block ice (only for parts built of wood alone).
    bool ice = false;
    /// The type each pig of the part becomes, in order (its own when unchanged).
    std::vector<std::string> pigTypes;
};

/// The horizontal extent of a part's blocks and pigs (their bounds, as the editor selects them).
struct PartSpan
{
    double left = 1e9;
    double right = -1e9;
    double middle() const { return 0.5 * (left + right); }
    double width() const { return right - left; }
};

PartSpan partSpan(const LevelDef& part, const Catalog& catalog);

/// Rounded to 0.1 mm: a quarter-metre part stretched by 1.25 keeps its exact edges (0.8125), and a shifted
/// coordinate its own decimals, while float noise (1.8800000000000001) goes.
double tidyMetres(double metres);

/// The stretches the generator draws from: a quarter apart, so that two of them look different.
inline constexpr double kPartStretches[] = {1.0, 1.25, 1.5};
/// A part is never stretched wider than this (a wide castle stays as it is).
inline constexpr double kMaxStretchedWidthM = 11.0;

/// A variation for the part, drawn from rng in a fixed order (stretch, mirror, ice, each pig) whatever the part allows:
/// a stretch among those that keep the part within kMaxStretchedWidthM, a mirror half the time when the part can be
/// mirrored, ice a quarter of the time when the part is all wood, and each small or medium pig made the other size
/// half the time when the new size does not run into a block (it keeps resting where it rested).
PartVariation drawPartVariation(const LevelDef& part, GeneratorRng& rng, const Catalog& catalog);

/// The part varied; coordinates and sizes rounded to whole millimetres.
LevelDef varyPart(const LevelDef& part, const PartVariation& variation, const Catalog& catalog);

} // namespace abalike

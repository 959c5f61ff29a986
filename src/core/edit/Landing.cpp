#include <abalike/edit/Landing.hpp>

#include <abalike/level/LevelCatalog.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/RestFindings.hpp>

#include "level/Outline.hpp"

#include <algorithm>

namespace abalike
{
namespace
{

/// A resting body may stand this far above its support: the rest test's own tolerance is looser.
constexpr double kLandedM = 0.001;

std::string landingName(const ObjectRef& ref)
{
    return (ref.kind == ObjectKind::Pig ? "pig " : "block ") + std::to_string(ref.index);
}

/// How far the body's lowest point is above the ground line (m).
double heightAboveGround(const LevelDef& level, const Catalog& catalog, const ObjectRef& ref)
{
    if (ref.kind == ObjectKind::Pig)
    {
        const PigDef& pig = level.pigs[ref.index];
        const PigType* type = catalog.findPig(pig.type);
        return pig.y - (type != nullptr ? type->radiusM : 0.0) - level.groundY;
    }
    double bottom = level.blocks[ref.index].y;
    for (const Outline& piece : blockOutlines(level.blocks[ref.index]))
        bottom = std::min(bottom, piece.bounds()[0].y);
    return bottom - level.groundY;
}

} // namespace

std::optional<std::string> whyNotLanded(const LevelDef& level, const Catalog& catalog,
                                        const std::vector<ObjectRef>& objects, double reachM)
{
    const Catalog seen = levelCatalog(level, catalog);
    std::optional<std::string> first;
    int floating = 0;
    for (const ObjectRef& ref : objects)
    {
        if (ref.kind != ObjectKind::Block && ref.kind != ObjectKind::Pig)
            continue;
        const bool pig = ref.kind == ObjectKind::Pig;
        if (ref.index >= (pig ? level.pigs.size() : level.blocks.size()))
            continue;
        const SupportGap gap = supportUnder(level, seen, pig, static_cast<int>(ref.index));
        if (!gap.support.empty() && gap.gapM <= kLandedM)
            continue;
        ++floating;
        if (first)
            continue;
        if (gap.support.empty())
            first = landingName(ref) + " is " + distanceInWords(heightAboveGround(level, seen, ref)) +
                    " above the ground with nothing under it: it falls when the level starts";
        else
            first = landingName(ref) + " floats " + distanceInWords(gap.gapM) + " above " + gap.support +
                    ", more than the " + distanceInWords(reachM) +
                    " the editor pulls a body down: it falls when the level starts; drag it " + "down onto " +
                    gap.support;
    }
    if (first && floating > 1)
        *first += " (and " + std::to_string(floating - 1) + " more placed the same way)";
    return first;
}

} // namespace abalike

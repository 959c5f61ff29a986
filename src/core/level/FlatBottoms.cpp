#include "level/FlatBottoms.hpp"

#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace abalike
{

namespace
{

/// The flat bottom's half-width as a share of the radius: Science Birds' Circle 0.42, CircleSmall 0.47, its pigs more.
constexpr double kFlatShare = 0.4;
/// A seated body's centre ends this far inside its support's edge: a round body there stays put.
constexpr double kInsetM = 0.02;

double tidy(double metres)
{
    return std::round(metres * 1e3) / 1e3;
}

/// A round body of the level, by reference so that it can be moved.
struct RoundBody
{
    bool pig;
    std::size_t index;
    double& x;
    double& y;
    double radius;
};

/// The radius of a round body (a circle block or a pig); none for any other.
std::optional<double> roundRadius(const LevelDef& level, const Catalog& catalog, bool pig, std::size_t index)
{
    if (pig)
    {
        const PigType* type = catalog.findPig(level.pigs[index].type);
        return type != nullptr ? type->radiusM : 0.25;
    }
    const BlockDef& block = level.blocks[index];
    if (block.shape == BlockShape::Circle)
        return 0.5 * block.widthM;
    return std::nullopt;
}

void forEachRoundBody(LevelDef& level, const Catalog& catalog, const std::function<void(RoundBody)>& visit)
{
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
        if (const std::optional<double> radius = roundRadius(level, catalog, false, i))
            visit({false, i, level.blocks[i].x, level.blocks[i].y, *radius});
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
        visit({true, i, level.pigs[i].x, level.pigs[i].y, *roundRadius(level, catalog, true, i)});
}

/// What the part of a round body's flat bottom from `from` to `to` would stand on.
SupportGap supportUnderFlat(const LevelDef& level, const Catalog& catalog, const RoundBody& body, double from,
                            double to)
{
    return supportUnderSpan(
        level, catalog,
        {from, to, body.y - body.radius, body.y + body.radius, body.pig ? -1 : static_cast<int>(body.index)});
}

/// A support close enough to be set onto.
bool reaches(const SupportGap& gap, double snapM)
{
    return !gap.support.empty() && std::abs(gap.gapM) <= snapM;
}

} // namespace

SupportGap supportUnderFlatBottom(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    const SupportGap under = supportUnder(level, catalog, pig, index);
    const auto i = static_cast<std::size_t>(index);
    const std::optional<double> radius = roundRadius(level, catalog, pig, i);
    if (!radius || (!under.support.empty() && under.gapM < *radius))
        return under;
    const double x = pig ? level.pigs[i].x : level.blocks[i].x;
    const double y = pig ? level.pigs[i].y : level.blocks[i].y;
    const double reach = kFlatShare * *radius;
    const SupportGap flat =
        supportUnderSpan(level, catalog, {x - reach, x + reach, y - *radius, y + *radius, pig ? -1 : index});
    return flat.support.empty() || (!under.support.empty() && under.gapM <= flat.gapM) ? under : flat;
}

std::vector<SeatedBody> seatRoundBodiesOnFlats(LevelDef& level, const Catalog& catalog, double snapM)
{
    std::vector<SeatedBody> seated;
    forEachRoundBody(level, catalog,
                     [&](RoundBody body)
                     {
                         const double reach = kFlatShare * body.radius;
                         const double x = body.x;
                         const SupportGap flat = supportUnderFlat(level, catalog, body, x - reach, x + reach);
                         if (!reaches(flat, snapM) || (x >= flat.supportLeftM && x <= flat.supportRightM))
                             return; // nothing near to stand on, or its centre is over it already
                         // Over a gap between two supports it rests on both edges (settleRoundBodiesIntoGaps).
                         if (reaches(supportUnderFlat(level, catalog, body, x - reach, x), snapM) &&
                             reaches(supportUnderFlat(level, catalog, body, x, x + reach), snapM))
                             return;
                         const double left = flat.supportLeftM + kInsetM;
                         const double right = flat.supportRightM - kInsetM;
                         const double to = tidy(left > right ? 0.5 * (flat.supportLeftM + flat.supportRightM)
                                                             : std::clamp(x, left, right));
                         const double past = x < flat.supportLeftM ? flat.supportLeftM - x : x - flat.supportRightM;
                         seated.push_back({body.pig, body.index, flat.support, past, to - x, 0.0});
                         body.x = to;
                     });
    return seated;
}

std::vector<SeatedBody> settleRoundBodiesIntoGaps(LevelDef& level, const Catalog& catalog, double snapM)
{
    std::vector<SeatedBody> settled;
    forEachRoundBody(level, catalog,
                     [&](RoundBody body)
                     {
                         if (reaches(supportUnder(level, catalog, body.pig, static_cast<int>(body.index)), snapM))
                             return; // its centre is over what it stands on
                         const double reach = kFlatShare * body.radius;
                         const SupportGap left = supportUnderFlat(level, catalog, body, body.x - reach, body.x);
                         const SupportGap right = supportUnderFlat(level, catalog, body, body.x, body.x + reach);
                         if (!reaches(left, snapM) || !reaches(right, snapM) ||
                             left.supportRightM >= right.supportLeftM)
                             return;
                         const double half = 0.5 * (right.supportLeftM - left.supportRightM);
                         const double top = (body.y - body.radius) - std::min(left.gapM, right.gapM);
                         const double toX = tidy(0.5 * (left.supportRightM + right.supportLeftM));
                         const double toY = tidy(top + std::sqrt(body.radius * body.radius - half * half));
                         if (std::abs(toX - body.x) < 5e-4 && std::abs(toY - body.y) < 5e-4)
                             return;
                         settled.push_back({body.pig, body.index, left.support + " and " + right.support, 2.0 * half,
                                            toX - body.x, toY - body.y});
                         body.x = toX;
                         body.y = toY;
                     });
    return settled;
}

} // namespace abalike

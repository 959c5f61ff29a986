#include "level/Outline.hpp"
#include "world/Fixtures.hpp"

#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelText.hpp>
#include <abalike/world/RestFindings.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

namespace abalike
{

namespace
{

/// A designed gap or overlap smaller than this is a body resting as built.
constexpr double kTouchM = 0.0005;
/// Supports are searched this far below a body's bottom (and this deep into it, for overlaps).
constexpr double kSearchM = 0.5;

/// Axis-aligned bounds of a shape as designed.
struct Bounds
{
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
};

Bounds rotatedBox(double x, double y, double w, double h, double angleDeg)
{
    const double a = angleDeg * std::numbers::pi / 180.0;
    const double hw = 0.5 * (std::abs(std::cos(a)) * w + std::abs(std::sin(a)) * h);
    const double hh = 0.5 * (std::abs(std::sin(a)) * w + std::abs(std::cos(a)) * h);
    return {x - hw, x + hw, y - hh, y + hh};
}

Bounds blockBounds(const BlockDef& b)
{
    if (b.shape == BlockShape::Circle)
        return {b.x - 0.5 * b.widthM, b.x + 0.5 * b.widthM, b.y - 0.5 * b.widthM, b.y + 0.5 * b.widthM};
    if (b.shape != BlockShape::Triangle)
        return rotatedBox(b.x, b.y, b.widthM, b.heightM, b.angleDeg);
    // A turned triangle's bounds are its corners', not its bounding box's turned: at 225 degrees its long side is
    // its flat bottom, through its centre.
    const std::array<Vec2, 2> corners = blockOutlines(b).front().bounds();
    return {corners[0].x, corners[1].x, corners[0].y, corners[1].y};
}

std::string metres(double m)
{
    std::ostringstream out;
    if (std::abs(m) < 0.01)
        out << std::fixed << std::setprecision(1) << m * 1000.0 << " mm";
    else if (std::abs(m) < 1.0)
        out << std::fixed << std::setprecision(1) << m * 100.0 << " cm";
    else
        out << std::fixed << std::setprecision(2) << m << " m";
    return out.str();
}

Bounds bodyBounds(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    if (!pig)
        return blockBounds(level.blocks[static_cast<std::size_t>(index)]);
    const PigDef& p = level.pigs[static_cast<std::size_t>(index)];
    const PigType* type = catalog.findPig(p.type);
    const double r = type != nullptr ? type->radiusM : 0.25;
    return {p.x - r, p.x + r, p.y - r, p.y + r};
}

std::string bodyName(const LevelDef& level, bool pig, int index)
{
    return pig ? "pig " + std::to_string(index)
               : "block " + std::to_string(index) + " (" + level.blocks[static_cast<std::size_t>(index)].material + ")";
}

/// The shortest decimal that holds y to 0.1 mm (what a designer would type).
std::string coordinate(double y)
{
    std::ostringstream out;
    out << std::setprecision(10) << std::round(y * 10000.0) / 10000.0;
    return out.str();
}

/// The highest point of a polygon's outline straight above or below x; none when x is outside it.
std::optional<double> topAt(const std::vector<Vec2>& polygon, double x)
{
    std::optional<double> top;
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        const auto& a = polygon[i];
        const auto& b = polygon[(i + 1) % polygon.size()];
        if (x < std::min(a.x, b.x) || x > std::max(a.x, b.x))
            continue;
        const double y = a.x == b.x ? std::max(a.y, b.y) : a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
        top = top ? std::max(*top, y) : y;
    }
    return top;
}

} // namespace

std::string RestFinding::message() const
{
    return fix.empty() ? what : what + "; " + fix;
}

namespace
{

/// A block something can rest on anywhere along its top: not round or pointed, turned by whole right angles.
bool hasFlatTop(const BlockDef& b)
{
    return b.shape != BlockShape::Circle && b.shape != BlockShape::Triangle &&
           std::abs(std::fmod(b.angleDeg, 90.0)) < 1e-9;
}

} // namespace

std::string distanceInWords(double m)
{
    return metres(m);
}

SupportGap supportUnder(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    const Bounds self = bodyBounds(level, catalog, pig, index);
    const bool round = pig || level.blocks[static_cast<std::size_t>(index)].shape == BlockShape::Circle;
    // A round body touches only under its centre; a flat one anywhere along its bottom.
    const double x = 0.5 * (self.left + self.right);
    return supportUnderSpan(
        level, catalog,
        {round ? x - 1e-6 : self.left, round ? x + 1e-6 : self.right, self.bottom, self.top, pig ? -1 : index});
}

SupportGap supportUnderSpan(const LevelDef& level, const Catalog& catalog, const SupportSpan& span)
{
    const double from = span.fromM;
    const double to = span.toM;
    const Bounds self{from, to, span.bottomM, span.topM};
    SupportGap best;
    double bestTop = -1e300;
    const auto consider = [&](const std::string& name, const Bounds& b, const Material* material)
    {
        if (b.right <= from || b.left >= to)
            return; // not under it
        if (b.top > self.bottom + kSearchM || b.top < self.bottom - kSearchM || b.top > 0.5 * (self.bottom + self.top))
            return; // too far below, or beside it rather than under it
        // A body on two posts rests on both: supports whose tops are level share it, and their extent is the span
        // its centre of mass must stay over.
        if (!best.support.empty() && std::abs(b.top - bestTop) <= kTouchM)
        {
            best.support += " and " + name;
            best.supportLeftM = std::min(best.supportLeftM, b.left);
            best.supportRightM = std::max(best.supportRightM, b.right);
            return;
        }
        if (b.top <= bestTop)
            return;
        bestTop = b.top;
        best.support = name;
        best.gapM = self.bottom - b.top;
        best.supportLeftM = b.left;
        best.supportRightM = b.right;
        best.supportIsSlippery = material != nullptr && material->friction < SupportGap::kSlipperyFriction;
        best.supportMaterial = material != nullptr ? material->name : std::string();
        best.supportFriction = material != nullptr ? material->friction : 0.0;
    };
    consider("the ground", {-1e9, 1e9, level.groundY - 1.0, level.groundY}, nullptr);
    for (std::size_t i = 0; i < level.terrain.size(); ++i)
    {
        const TerrainDef& t = level.terrain[i];
        if (t.isPolygon())
        {
            // Only where its top is flat under the body is there one gap to name.
            const std::optional<double> a = topAt(t.points, from);
            const std::optional<double> b = topAt(t.points, 0.5 * (from + to));
            const std::optional<double> c = topAt(t.points, to);
            if (a && b && c && std::abs(*a - *b) < 1e-3 && std::abs(*b - *c) < 1e-3)
                consider("terrain " + std::to_string(i), {t.x - 0.5 * t.widthM, t.x + 0.5 * t.widthM, *b - 1.0, *b},
                         nullptr);
            continue;
        }
        if (std::abs(std::fmod(t.angleDeg, 90.0)) < 1e-9) // a tilted hill's top is not flat: no single gap
            consider("terrain " + std::to_string(i), rotatedBox(t.x, t.y, t.widthM, t.heightM, t.angleDeg), nullptr);
    }
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
    {
        const BlockDef& b = level.blocks[i];
        if (static_cast<int>(i) == span.skipBlock)
            continue;
        if (hasFlatTop(b))
            consider("block " + std::to_string(i) + " (" + b.material + ")", blockBounds(b),
                     catalog.findMaterial(b.material));
    }
    return best;
}

namespace
{

/// What is wrong with one body as built (on the level as fixed so far) and the change that would fix it. `own` is
/// false when nothing about the body itself is wrong: it only moved.
struct Defect
{
    std::string what;
    std::string fix;
    bool own = false;
    std::optional<double> y; ///< the fix as numbers: the body's new y, x or angle
    std::optional<double> x;
    std::optional<double> angleDeg;
    /// A leaning group's fix: the x that stacks the body and the bodies on it (groupMembers) straight over the middle
    /// of what it stands on.
    std::optional<double> groupX;
    std::vector<std::pair<bool, int>> groupMembers; ///< (pig, index) of the bodies on it
    /// A floating or sunk body's fix that carries its load: the bodies on it (groupMembers) move up or down by this
    /// much with it.
    std::optional<double> groupDy;
};

/// A body's mass as the world makes it: areal density times area.
double massOf(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    if (pig)
    {
        const PigType* type = catalog.findPig(level.pigs[static_cast<std::size_t>(index)].type);
        return type != nullptr ? type->densityKgPerM2 * std::numbers::pi * type->radiusM * type->radiusM : 1.0;
    }
    const BlockDef& b = level.blocks[static_cast<std::size_t>(index)];
    const Material* material = catalog.findMaterial(b.material);
    return (material != nullptr ? material->densityKgPerM2 : 1.0) * designedArea(b);
}

/// A group that moves with nothing wrong with any one body: a stack leaning as a whole. Its centre of mass past the
/// span of what the lowest rests on is the lean; the fix moves the group back over it.
void leanOf(Defect& d, const LevelDef& level, const Catalog& catalog, bool pig, int index,
            const std::vector<std::pair<bool, int>>& above)
{
    const SupportGap under = supportUnder(level, catalog, pig, index);
    if (under.support.empty() || above.empty())
        return;
    double mass = 0.0;
    double moment = 0.0;
    const auto add = [&](bool p, int i)
    {
        const double m = massOf(level, catalog, p, i);
        mass += m;
        moment += m * (p ? level.pigs[static_cast<std::size_t>(i)].x : level.blocks[static_cast<std::size_t>(i)].x);
    };
    add(pig, index);
    for (const auto& [p, i] : above)
        add(p, i);
    const double centre = moment / mass;
    if (centre >= under.supportLeftM && centre <= under.supportRightM)
        return;
    const bool right = centre > under.supportRightM;
    const double past = right ? centre - under.supportRightM : under.supportLeftM - centre;
    std::ostringstream what;
    what << "leans: with the " << above.size() << (above.size() == 1 ? " body" : " bodies")
         << " on it, its centre of mass is " << metres(past) << " past " << under.support << "'s "
         << (right ? "right" : "left") << " edge, so the stack tips over";
    d.what = what.str();
    d.groupX = std::round(0.5 * (under.supportLeftM + under.supportRightM) * 1e4) / 1e4;
    d.groupMembers = above;
    d.fix = "stack it and the bodies on it straight over " + under.support + " (set x = " + coordinate(*d.groupX) +
            " for each), or widen what it stands on";
}

/// A second support for a body fallen past its support's edge (a plank pushed off one of its two posts): a block
/// whose flat top is level with that support's, beside it, and the x that centres the body across both, when the
/// body is long enough to reach over each by a centimetre. The one that moves it least.
struct SecondSupport
{
    std::string name;
    double centreX = 0.0;
};

std::optional<SecondSupport> secondSupport(const LevelDef& level, bool pig, int index, const SupportGap& under)
{
    if (pig)
        return std::nullopt;
    const BlockDef& self = level.blocks[static_cast<std::size_t>(index)];
    const Bounds own = blockBounds(self);
    const double half = 0.5 * (own.right - own.left);
    const double supportTop = own.bottom - under.gapM;
    std::optional<SecondSupport> best;
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
    {
        const BlockDef& b = level.blocks[i];
        if (static_cast<int>(i) == index || !hasFlatTop(b))
            continue;
        const Bounds other = blockBounds(b);
        const bool beside = other.left >= under.supportRightM || other.right <= under.supportLeftM;
        if (!beside || std::abs(other.top - supportTop) > kTouchM)
            continue;
        const double centre =
            std::round(0.5 * (std::min(under.supportLeftM, other.left) + std::max(under.supportRightM, other.right)) *
                       1e3) /
            1e3;
        const bool otherRight = other.left >= under.supportRightM;
        const double innerLeft = otherRight ? under.supportRightM : other.right;
        const double innerRight = otherRight ? other.left : under.supportLeftM;
        if (centre - half > innerLeft - 0.01 || centre + half < innerRight + 0.01)
            continue;
        if (!best || std::abs(centre - self.x) < std::abs(best->centreX - self.x))
            best = SecondSupport{"block " + std::to_string(i) + " (" + b.material + ")", centre};
    }
    return best;
}

/// A ball or a triangle's slope right under a body, its top from 10 cm under the body's bottom to 5 cm into it:
/// supportUnder passes over them, as nothing rests on them still; the finding names them.
struct RoundTop
{
    std::string name; ///< "the round top of block 12 (wood)", "the sloped top of block 3 (ice)"
    double gapM = 0.0;
    bool round = true; ///< a ball, else a triangle
};

std::optional<RoundTop> roundTopUnder(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    const Bounds self = bodyBounds(level, catalog, pig, index);
    std::optional<RoundTop> found;
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
    {
        const BlockDef& b = level.blocks[i];
        if ((!pig && static_cast<int>(i) == index) || hasFlatTop(b))
            continue;
        const Bounds under = blockBounds(b);
        const bool below = under.top <= 0.5 * (self.bottom + self.top) && under.top >= self.bottom - 0.1 &&
                           under.top <= self.bottom + 0.05;
        if (!below || under.right <= self.left || under.left >= self.right ||
            (found && self.bottom - under.top >= found->gapM))
            continue;
        found = RoundTop{std::string(b.shape == BlockShape::Circle ? "the round top of " : "the sloped top of ") +
                             "block " + std::to_string(i) + " (" + b.material + ")",
                         self.bottom - under.top, b.shape == BlockShape::Circle};
    }
    return found;
}

Defect defectOf(const LevelDef& level, const Catalog& catalog, bool pig, int index, bool moved, double movedM)
{
    Defect d;
    const std::size_t i = static_cast<std::size_t>(index);
    const double y = pig ? level.pigs[i].y : level.blocks[i].y;
    const double x = pig ? level.pigs[i].x : level.blocks[i].x;
    const SupportGap under = supportUnder(level, catalog, pig, index);
    std::ostringstream what;
    const BlockDef* block = pig ? nullptr : &level.blocks[i];
    const bool leaning = block != nullptr && block->shape != BlockShape::Circle &&
                         std::abs(std::remainder(block->angleDeg, 90.0)) > 1e-9;
    double pastCorner = 0.0;
    if (leaning)
    {
        // Where its lowest corner is: a box tilted on one corner tips unless its centre is above that corner.
        const double a = block->angleDeg * std::numbers::pi / 180.0;
        double lowestY = 1e300;
        double cornerX = x;
        for (const double sx : {-0.5, 0.5})
            for (const double sy : {-0.5, 0.5})
            {
                const double cx = sx * block->widthM;
                const double cy = sy * block->heightM;
                const double py = y + std::sin(a) * cx + std::cos(a) * cy;
                if (py < lowestY - 1e-9)
                {
                    lowestY = py;
                    cornerX = x + std::cos(a) * cx - std::sin(a) * cy;
                }
            }
        pastCorner = std::abs(x - cornerX);
    }
    d.own = true;
    if (leaning && moved && pastCorner > 0.01)
    {
        what << "leans " << std::fixed << std::setprecision(0) << std::abs(std::remainder(block->angleDeg, 90.0))
             << "\u00B0 on one corner with its centre of mass " << metres(pastCorner) << " past it, so it tips over";
        d.angleDeg = 90.0 * std::round(block->angleDeg / 90.0);
        d.fix = "set angle_deg = " + coordinate(*d.angleDeg) + " or lean it against something";
    }
    else if (const std::optional<RoundTop> top = moved && (under.support.empty() || under.gapM > kTouchM)
                                                     ? roundTopUnder(level, catalog, pig, index)
                                                     : std::nullopt)
    {
        const char* off = top->round ? "rolls off" : "slides off";
        if (top->gapM > 0.01)
            what << "drops " << metres(top->gapM) << " onto " << top->name << ", " << off;
        else
            what << off << " " << top->name;
    }
    else if (!under.support.empty() && std::abs(under.gapM) > kTouchM)
    {
        if (under.gapM > 0.0)
            what << "floats " << metres(under.gapM) << " above " << under.support;
        else
            what << "overlaps " << under.support << " by " << metres(-under.gapM);
        d.y = y - under.gapM;
        d.fix = "set y = " + coordinate(*d.y);
    }
    else if (!under.support.empty() && (x < under.supportLeftM || x > under.supportRightM))
    {
        const bool right = x > under.supportRightM;
        const double past = right ? x - under.supportRightM : under.supportLeftM - x;
        what << "falls: its centre of mass is " << metres(past) << " past " << under.support << "'s edge";
        if (const std::optional<SecondSupport> other = secondSupport(level, pig, index, under))
        {
            // A plank pushed off one of its posts: back across both.
            d.x = other->centreX;
            d.fix =
                "put it back across " + under.support + " and " + other->name + " (set x = " + coordinate(*d.x) + ")";
        }
        else
        {
            d.x = right ? under.supportRightM - 0.01 : under.supportLeftM + 0.01;
            d.fix = "move it " + metres(past + 0.01) + (right ? " left" : " right") + " (set x = " + coordinate(*d.x) +
                    ") or support its centre";
        }
    }
    else if (under.supportIsSlippery && moved)
        what << "slides off " << under.support << " (" << under.supportMaterial << " is slippery: friction "
             << under.supportFriction << ")";
    else if (under.support.empty())
        what << "falls: nothing is under it";
    else
    {
        d.own = false;
        if (moved)
            what << "moves " << metres(movedM) << " while left alone";
    }
    d.what = what.str();
    return d;
}

/// The level with a defect's fix applied to the body.
void applyFix(LevelDef& level, bool pig, int index, const Defect& d)
{
    if (d.groupX)
    {
        std::vector<std::pair<bool, int>> group = d.groupMembers;
        group.emplace_back(pig, index);
        for (const auto& [p, i] : group)
            (p ? level.pigs[static_cast<std::size_t>(i)].x : level.blocks[static_cast<std::size_t>(i)].x) = *d.groupX;
        return;
    }
    if (d.groupDy)
        for (const auto& [p, member] : d.groupMembers)
            (p ? level.pigs[static_cast<std::size_t>(member)].y : level.blocks[static_cast<std::size_t>(member)].y) +=
                *d.groupDy;
    const std::size_t i = static_cast<std::size_t>(index);
    if (pig)
    {
        level.pigs[i].y = d.y.value_or(level.pigs[i].y);
        level.pigs[i].x = d.x.value_or(level.pigs[i].x);
        return;
    }
    level.blocks[i].y = d.y.value_or(level.blocks[i].y);
    level.blocks[i].x = d.x.value_or(level.blocks[i].x);
    level.blocks[i].angleDeg = d.angleDeg.value_or(level.blocks[i].angleDeg);
}

std::string pointerOf(const BodyRest& body)
{
    return (body.kind == EntityKind::Pig ? "/pigs/" : "/blocks/") + std::to_string(body.defIndex);
}

bool failsIn(const RestReport& report, const std::string& pointer)
{
    for (const BodyRest& body : report.bodies)
        if (pointerOf(body) == pointer)
            return body.maxDisplacementM > report.toleranceM || body.damaged || body.destroyed;
    return false;
}

} // namespace

std::vector<RestFinding> restFindings(const LevelDef& level, const Catalog& catalog, const RestReport& report)
{
    // What a body rests on is told with the level's own materials ("ice (friction 0.7)" where it sets it); the
    // rest test of a fix builds its world from the base catalog and the level, as every world does.
    const Catalog seen = levelCatalog(level, catalog);
    // The bodies that fail. Those with something wrong of their own (floating, overlapping, past their supports'
    // edge, leaning, on nothing) are the causes; the rest only follow them and are listed under the cause that
    // touches them or is nearest, started no later. When no body has a defect of its own (a stack that leans as a
    // whole), the first to move, the lowest of those that start together, stands for the group.
    struct Failing
    {
        std::size_t k;
        bool pig;
        int index;
        Bounds bounds;
        double startS;
        Defect defect;
    };
    std::vector<Failing> failing;
    for (std::size_t k = 0; k < report.bodies.size(); ++k)
    {
        const BodyRest& body = report.bodies[k];
        const bool moved = body.maxDisplacementM > report.toleranceM;
        if (!moved && !body.damaged && !body.destroyed)
            continue;
        const bool pig = body.kind == EntityKind::Pig;
        failing.push_back({k, pig, body.defIndex, bodyBounds(level, seen, pig, body.defIndex),
                           body.startedS.value_or(1e300),
                           defectOf(level, seen, pig, body.defIndex, moved, body.maxDisplacementM)});
    }
    std::vector<std::size_t> causes;
    for (std::size_t i = 0; i < failing.size(); ++i)
        if (failing[i].defect.own)
            causes.push_back(i);
    if (causes.empty() && !failing.empty())
    {
        std::size_t first = 0;
        for (std::size_t i = 1; i < failing.size(); ++i)
            if (failing[i].startS < failing[first].startS ||
                (failing[i].startS == failing[first].startS && failing[i].bounds.bottom < failing[first].bounds.bottom))
                first = i;
        causes.push_back(first);
    }
    // Bottom up: a fix above another is worked out on the level with the one below fixed.
    std::sort(causes.begin(), causes.end(),
              [&](std::size_t a, std::size_t b) { return failing[a].bounds.bottom < failing[b].bounds.bottom; });
    std::map<std::size_t, std::vector<std::size_t>> follow;
    for (std::size_t i = 0; i < failing.size(); ++i)
    {
        if (std::find(causes.begin(), causes.end(), i) != causes.end())
            continue;
        std::optional<std::size_t> best;
        double bestDistance = 1e300;
        for (const std::size_t c : causes)
        {
            const Bounds& a = failing[c].bounds;
            const Bounds& b = failing[i].bounds;
            const double dx = std::max({0.0, a.left - b.right, b.left - a.right});
            const double dy = std::max({0.0, a.bottom - b.top, b.bottom - a.top});
            const double distance = std::hypot(dx, dy) + (failing[c].startS <= failing[i].startS ? 0.0 : 1e6);
            if (distance < bestDistance)
            {
                bestDistance = distance;
                best = c;
            }
        }
        if (best)
            follow[*best].push_back(i);
    }

    // Every fix worked out bottom up (a fix above another assumes the one below is made), then all of them tried at
    // once: a fix is suggested only when, with them, its body and what follows it stand the rest check.
    LevelDef fixed = level;
    std::vector<Defect> defects;
    for (const std::size_t c : causes)
    {
        const Failing& cause = failing[c];
        const BodyRest& body = report.bodies[cause.k];
        defects.push_back(cause.defect.own ? defectOf(fixed, seen, cause.pig, cause.index,
                                                      body.maxDisplacementM > report.toleranceM, body.maxDisplacementM)
                                           : cause.defect);
        std::vector<std::pair<bool, int>> above;
        for (const std::size_t i : follow[c])
            if (failing[i].bounds.bottom >= cause.bounds.bottom)
                above.emplace_back(failing[i].pig, failing[i].index);
        if (!cause.defect.own)
            leanOf(defects.back(), fixed, seen, cause.pig, cause.index, above);
        else if (Defect& d = defects.back(); d.y && !d.x && !d.angleDeg && !d.groupX && !above.empty())
        {
            // A body set down onto (or up out of) its support takes what rests on it along: set alone, its load
            // would be left floating (or sunk) in its turn.
            const double y = cause.pig ? fixed.pigs[static_cast<std::size_t>(cause.index)].y
                                       : fixed.blocks[static_cast<std::size_t>(cause.index)].y;
            d.groupDy = *d.y - y;
            d.groupMembers = above;
            std::ostringstream with;
            with << std::fixed << std::setprecision(1) << " (and the "
                 << (above.size() == 1 ? std::string("body on it ") : std::to_string(above.size()) + " bodies on it ")
                 << (*d.groupDy < 0 ? "down" : "up") << " by the same " << std::abs(*d.groupDy) * 100.0 << " cm)";
            const std::size_t orAt = d.fix.find(" or ");
            d.fix.insert(orAt == std::string::npos ? d.fix.size() : orAt, with.str());
        }
        if (!defects.back().fix.empty())
            applyFix(fixed, cause.pig, cause.index, defects.back());
    }
    const bool anyFix = std::any_of(defects.begin(), defects.end(), [](const Defect& d) { return !d.fix.empty(); });
    const std::optional<RestReport> withFixes =
        anyFix ? std::optional<RestReport>(checkRest(fixed, catalog, report.seconds, {}, report.toleranceM))
               : std::nullopt;

    // Listed in the file's order (blocks, then pigs), as a designer reads the file.
    std::vector<std::size_t> order(causes.size());
    for (std::size_t n = 0; n < order.size(); ++n)
        order[n] = n;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return failing[causes[a]].k < failing[causes[b]].k; });
    std::vector<RestFinding> findings;
    for (const std::size_t n : order)
    {
        const Failing& cause = failing[causes[n]];
        const BodyRest& body = report.bodies[cause.k];
        const Defect& d = defects[n];
        RestFinding f;
        f.pointer = pointerOf(body);
        for (const std::size_t i : follow[causes[n]])
            f.consequences.push_back(pointerOf(report.bodies[failing[i].k]));
        std::ostringstream what;
        what << d.what;
        if (body.destroyed)
            what << (what.tellp() > 0 ? " and " : "") << "breaks before any shot";
        else if (body.damaged)
            what << (what.tellp() > 0 ? " and " : "") << "takes damage before any shot";
        if (!f.consequences.empty())
        {
            what << "; it moves " << f.consequences.size() << (f.consequences.size() == 1 ? " body" : " bodies")
                 << " with it: ";
            const std::vector<std::size_t>& others = follow[causes[n]];
            for (std::size_t i = 0; i < others.size(); ++i)
                what << (i == 0                   ? ""
                         : i + 1 == others.size() ? " and "
                                                  : ", ")
                     << bodyName(level, failing[others[i]].pig, failing[others[i]].index);
        }
        if (!d.fix.empty())
        {
            bool works = !failsIn(*withFixes, f.pointer);
            for (const std::string& pointer : f.consequences)
                works = works && !failsIn(*withFixes, pointer);
            if (works)
            {
                f.fix = d.fix;
                f.fixY = d.y;
                f.fixX = d.x;
                f.fixAngleDeg = d.angleDeg;
                f.groupX = d.groupX;
                f.groupDy = d.groupDy;
                if (d.groupDy)
                    for (const auto& [p, member] : d.groupMembers)
                        f.movedWith.push_back((p ? "/pigs/" : "/blocks/") + std::to_string(member));
                const double y = cause.pig ? level.pigs[static_cast<std::size_t>(cause.index)].y
                                           : level.blocks[static_cast<std::size_t>(cause.index)].y;
                if (d.y && std::abs(*d.y - y) <= RestFinding::kMaxSnapM)
                    f.snapY = d.y;
            }
            else
                what << "; " << d.fix.substr(0, d.fix.find(" or ")) << " was tried and it still moves, so no fix is "
                     << "suggested";
        }
        f.what = what.str();
        findings.push_back(std::move(f));
    }
    return findings;
}

std::vector<LevelIssue> restIssues(const LevelDef& level, const Catalog& catalog, const RestReport& report,
                                   const std::string& file)
{
    std::vector<LevelIssue> issues;
    if (report.passed())
        return issues;
    for (const RestFinding& finding : restFindings(level, catalog, report))
        issues.push_back({file, 0, 0, finding.pointer, finding.message()});
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.good() || in.eof())
    {
        try
        {
            locateIssues(issues, text, file);
        }
        catch (const std::exception&)
        {
            // The file changed under us into something that is not JSON: the issues keep their pointers.
        }
    }
    return issues;
}

} // namespace abalike

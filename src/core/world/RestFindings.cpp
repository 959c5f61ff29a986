#include <abalike/level/LevelText.hpp>
#include <abalike/world/RestFindings.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
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
    return rotatedBox(b.x, b.y, b.widthM, b.heightM, b.angleDeg);
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

/// The shortest decimal that holds y to 0.1 mm (what a designer would type).
std::string coordinate(double y)
{
    std::ostringstream out;
    out << std::setprecision(10) << std::round(y * 10000.0) / 10000.0;
    return out.str();
}

/// The highest point of a polygon's outline straight above or below x; none when x is outside it.
std::optional<double> topAt(const std::vector<std::array<double, 2>>& polygon, double x)
{
    std::optional<double> top;
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        const auto& a = polygon[i];
        const auto& b = polygon[(i + 1) % polygon.size()];
        if (x < std::min(a[0], b[0]) || x > std::max(a[0], b[0]))
            continue;
        const double y = a[0] == b[0] ? std::max(a[1], b[1]) : a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
        top = top ? std::max(*top, y) : y;
    }
    return top;
}

} // namespace

std::string RestFinding::message() const
{
    return fix.empty() ? what : what + "; " + fix;
}

SupportGap supportUnder(const LevelDef& level, const Catalog& catalog, bool pig, int index)
{
    Bounds self;
    bool round = false;
    if (pig)
    {
        const PigDef& p = level.pigs[static_cast<std::size_t>(index)];
        const PigType* type = catalog.findPig(p.type);
        const double r = type != nullptr ? type->radiusM : 0.25;
        self = {p.x - r, p.x + r, p.y - r, p.y + r};
        round = true;
    }
    else
    {
        const BlockDef& b = level.blocks[static_cast<std::size_t>(index)];
        self = blockBounds(b);
        round = b.shape == BlockShape::Circle;
    }
    // A round body touches only under its centre; a flat one anywhere along its bottom.
    const double x = 0.5 * (self.left + self.right);
    const double from = round ? x - 1e-6 : self.left;
    const double to = round ? x + 1e-6 : self.right;
    SupportGap best;
    double bestTop = -1e300;
    const auto consider = [&](const std::string& name, const Bounds& b, const Material* material)
    {
        if (b.right <= from || b.left >= to)
            return; // not under it
        if (b.top > self.bottom + kSearchM || b.top < self.bottom - kSearchM || b.top > 0.5 * (self.bottom + self.top))
            return; // too far below, or beside it rather than under it
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
        if (!pig && static_cast<int>(i) == index)
            continue;
        const bool flatTop = b.shape != BlockShape::Circle && b.shape != BlockShape::Triangle &&
                             std::abs(std::fmod(b.angleDeg, 90.0)) < 1e-9;
        if (flatTop)
            consider("block " + std::to_string(i) + " (" + b.material + ")", blockBounds(b),
                     catalog.findMaterial(b.material));
    }
    return best;
}

std::vector<RestFinding> restFindings(const LevelDef& level, const Catalog& catalog, const RestReport& report)
{
    std::vector<RestFinding> findings;
    for (const BodyRest& body : report.bodies)
    {
        const bool moved = body.maxDisplacementM > report.toleranceM;
        if (!moved && !body.damaged && !body.destroyed)
            continue;
        const bool pig = body.kind == EntityKind::Pig;
        RestFinding f;
        f.pointer = (pig ? "/pigs/" : "/blocks/") + std::to_string(body.defIndex);
        const double y = pig ? level.pigs[static_cast<std::size_t>(body.defIndex)].y
                             : level.blocks[static_cast<std::size_t>(body.defIndex)].y;
        const double x = pig ? level.pigs[static_cast<std::size_t>(body.defIndex)].x
                             : level.blocks[static_cast<std::size_t>(body.defIndex)].x;
        const SupportGap under = supportUnder(level, catalog, pig, body.defIndex);
        std::ostringstream what;
        const BlockDef* block = pig ? nullptr : &level.blocks[static_cast<std::size_t>(body.defIndex)];
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
        if (leaning && moved && pastCorner > 0.01)
        {
            what << "leans " << std::fixed << std::setprecision(0) << std::abs(std::remainder(block->angleDeg, 90.0))
                 << "\u00B0 on one corner with its centre of mass " << metres(pastCorner)
                 << " past it, so it tips over";
            f.fix = "set angle_deg = " + coordinate(90.0 * std::round(block->angleDeg / 90.0)) +
                    " or lean it against something";
        }
        else if (!under.support.empty() && under.gapM > kTouchM)
        {
            what << "floats " << metres(under.gapM) << " above " << under.support;
            f.fix = "set y = " + coordinate(y - under.gapM);
            if (under.gapM <= RestFinding::kMaxSnapM)
                f.snapY = y - under.gapM;
        }
        else if (!under.support.empty() && under.gapM < -kTouchM)
        {
            what << "overlaps " << under.support << " by " << metres(-under.gapM);
            f.fix = "set y = " + coordinate(y - under.gapM);
            if (-under.gapM <= RestFinding::kMaxSnapM)
                f.snapY = y - under.gapM;
        }
        else if (!under.support.empty() && (x < under.supportLeftM || x > under.supportRightM))
        {
            const double past = x < under.supportLeftM ? under.supportLeftM - x : x - under.supportRightM;
            what << "falls: its centre of mass is " << metres(past) << " past " << under.support << "'s edge";
            f.fix =
                "move it " + metres(past) + (x < under.supportLeftM ? " right" : " left") + " or support its centre";
        }
        else if (under.supportIsSlippery && moved)
            what << "slides off " << under.support << " (" << under.supportMaterial << " is slippery: friction "
                 << under.supportFriction << ")";
        else if (under.support.empty())
            what << "falls: nothing is under it";
        else if (moved)
            what << "moves " << metres(body.maxDisplacementM) << " while left alone";
        if (body.destroyed)
            what << (what.tellp() > 0 ? " and " : "") << "breaks before any shot";
        else if (body.damaged)
            what << (what.tellp() > 0 ? " and " : "") << "takes damage before any shot";
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

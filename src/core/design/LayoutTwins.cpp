#include <abalike/design/LayoutTwins.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace abalike
{

namespace
{

bool sameSize(double a, double b)
{
    return std::abs(a - b) <= kTwinSizeShare * std::max(a, b) + 1e-9;
}

/// A body as the measure sees it: what it is (kind, shape or pig type, size, angle) and where.
struct TwinBody
{
    int kind = 0; ///< 0 block, 1 pig, 2 terrain
    std::string what;
    double widthM = 0.0;
    double heightM = 0.0;
    double angleDeg = 0.0;
    double x = 0.0;
    double y = 0.0;

    bool sameAs(const TwinBody& o) const
    {
        return kind == o.kind && what == o.what && sameSize(widthM, o.widthM) && sameSize(heightM, o.heightM) &&
               std::abs(angleDeg - o.angleDeg) < 0.5;
    }
};

std::vector<TwinBody> twinBodies(const LevelDef& level)
{
    std::vector<TwinBody> bodies;
    for (const BlockDef& b : level.blocks)
        bodies.push_back({0, std::to_string(static_cast<int>(b.shape)), b.widthM, b.heightM, b.angleDeg, b.x, b.y});
    for (const PigDef& p : level.pigs)
        bodies.push_back({1, p.type, 0.0, 0.0, 0.0, p.x, p.y});
    for (const TerrainDef& t : level.terrain)
        bodies.push_back({2, "", t.widthM, t.heightM, t.angleDeg, t.x, t.y});
    double left = std::numeric_limits<double>::infinity();
    for (const TwinBody& body : bodies)
        left = std::min(left, body.x);
    for (TwinBody& body : bodies)
        body.x -= left;
    return bodies;
}

/// How many bodies of a find a partner in b; each body of b partners at most one, the nearest sideways.
std::size_t partnered(const std::vector<TwinBody>& a, const std::vector<TwinBody>& b)
{
    std::vector<bool> used(b.size(), false);
    std::size_t count = 0;
    for (const TwinBody& body : a)
    {
        std::size_t best = b.size();
        double bestGap = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < b.size(); ++j)
        {
            const double gap = std::abs(body.x - b[j].x);
            if (!used[j] && body.sameAs(b[j]) && gap <= kTwinSidewaysM && std::abs(body.y - b[j].y) <= kTwinVerticalM &&
                gap < bestGap)
            {
                best = j;
                bestGap = gap;
            }
        }
        if (best < b.size())
        {
            used[best] = true;
            ++count;
        }
    }
    return count;
}

} // namespace

double layoutTwinShare(const LevelDef& a, const LevelDef& b)
{
    const std::vector<TwinBody> ba = twinBodies(a);
    const std::vector<TwinBody> bb = twinBodies(b);
    if (ba.empty() || bb.empty())
        return 0.0;
    return std::min(static_cast<double>(partnered(ba, bb)) / static_cast<double>(ba.size()),
                    static_cast<double>(partnered(bb, ba)) / static_cast<double>(bb.size()));
}

} // namespace abalike

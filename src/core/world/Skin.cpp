#include "world/Skin.hpp"

namespace abalike
{

std::vector<b2Vec2> insetPolygon(const std::vector<b2Vec2>& outline)
{
    const std::size_t n = outline.size();
    std::vector<b2Vec2> inset(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        // Vertex i moves along the bisector of its two edges far enough that both edges move in by the inset.
        const b2Vec2 prev = outline[(i + n - 1) % n];
        const b2Vec2 here = outline[i];
        const b2Vec2 next = outline[(i + 1) % n];
        b2Vec2 e1 = here - prev;
        b2Vec2 e2 = next - here;
        e1.Normalize();
        e2.Normalize();
        const b2Vec2 n1(-e1.y, e1.x); // inward normals of a counter-clockwise polygon
        const b2Vec2 n2(-e2.y, e2.x);
        b2Vec2 bisector = n1 + n2;
        bisector.Normalize();
        const float cosHalf = b2Dot(bisector, n1);
        inset[i] = here + (kPolygonInset / cosHalf) * bisector;
    }
    return inset;
}

std::vector<b2Vec2> chamferCorners(const std::vector<b2Vec2>& polygon, float chamfer, const std::vector<bool>& cut)
{
    const std::size_t n = polygon.size();
    std::vector<b2Vec2> out;
    out.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const b2Vec2 here = polygon[i];
        if (!(chamfer > 0.0f) || (!cut.empty() && !cut[i]))
        {
            out.push_back(here);
            continue;
        }
        b2Vec2 toPrev = polygon[(i + n - 1) % n] - here;
        b2Vec2 toNext = polygon[(i + 1) % n] - here;
        toPrev.Normalize();
        toNext.Normalize();
        out.push_back(here + chamfer * toPrev);
        out.push_back(here + chamfer * toNext);
    }
    return out;
}

} // namespace abalike

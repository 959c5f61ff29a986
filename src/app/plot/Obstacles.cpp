#include "plot/Obstacles.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{

bool overlaps(const PixelBox& a, const PixelBox& b)
{
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/// Liang-Barsky: does the segment pass through the box?
bool segmentCrosses(double x0, double y0, double x1, double y1, const PixelBox& box)
{
    const double dx = x1 - x0, dy = y1 - y0;
    double t0 = 0.0, t1 = 1.0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - box.x0, box.x1 - x0, y0 - box.y0, box.y1 - y0};
    for (int i = 0; i < 4; ++i)
    {
        if (p[i] == 0.0)
        {
            if (q[i] < 0.0)
                return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return false;
    }
    return true;
}

} // namespace

void Obstacles::addSegment(double x0, double y0, double x1, double y1)
{
    m_segments.push_back({x0, y0, x1, y1});
}

void Obstacles::addBox(const PixelBox& box)
{
    m_boxes.push_back(box);
}

int Obstacles::hits(const PixelBox& box) const
{
    int count = 0;
    for (const Segment& s : m_segments)
        count += segmentCrosses(s.x0, s.y0, s.x1, s.y1, box) ? 1 : 0;
    for (const PixelBox& b : m_boxes)
        count += overlaps(b, box) ? 1 : 0;
    return count;
}

} // namespace abalike::app

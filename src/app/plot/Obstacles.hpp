#pragma once

#include <vector>

namespace abalike::app
{

/// An axis-aligned rectangle in pixels (y down).
struct PixelBox
{
    double x0 = 0.0;
    double y0 = 0.0;
    double x1 = 0.0;
    double y1 = 0.0;

    bool contains(const PixelBox& inner) const
    {
        return inner.x0 >= x0 && inner.y0 >= y0 && inner.x1 <= x1 && inner.y1 <= y1;
    }
};

/// What is already drawn on a plot (line segments and boxes, in pixels), so the legend and callout texts can be
/// placed where they hide no data.
class Obstacles
{
public:
    void addSegment(double x0, double y0, double x1, double y1);
    void addBox(const PixelBox& box);

    /// How many obstacles the box touches.
    int hits(const PixelBox& box) const;

private:
    struct Segment
    {
        double x0, y0, x1, y1;
    };
    std::vector<Segment> m_segments;
    std::vector<PixelBox> m_boxes;
};

} // namespace abalike::app

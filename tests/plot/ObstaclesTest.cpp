#include "plot/Obstacles.hpp"

#include <gtest/gtest.h>

namespace abalike::app
{
namespace
{

TEST(ObstaclesTest, SegmentsCountWhenTheyCrossTheBox)
{
    Obstacles o;
    const PixelBox box{10, 10, 20, 20};
    o.addSegment(0, 0, 30, 30); // diagonal through the box
    EXPECT_EQ(o.hits(box), 1);
    o.addSegment(0, 25, 30, 25); // below it
    o.addSegment(0, 0, 9, 30);   // left of it
    EXPECT_EQ(o.hits(box), 1);
    o.addSegment(15, 15, 16, 16); // inside it
    o.addSegment(15, 0, 15, 12);  // ending in it
    EXPECT_EQ(o.hits(box), 3);
    o.addSegment(0, 30, 30, 30); // horizontal, outside
    EXPECT_EQ(o.hits(box), 3);
}

TEST(ObstaclesTest, BoxesCountWhenTheyOverlap)
{
    Obstacles o;
    o.addBox({0, 0, 10, 10});
    EXPECT_EQ(o.hits({9, 9, 12, 12}), 1);
    EXPECT_EQ(o.hits({10, 0, 12, 12}), 0); // touching edges do not overlap
    EXPECT_TRUE((PixelBox{0, 0, 10, 10}.contains({1, 1, 9, 9})));
    EXPECT_FALSE((PixelBox{0, 0, 10, 10}.contains({1, 1, 11, 9})));
}

} // namespace
} // namespace abalike::app

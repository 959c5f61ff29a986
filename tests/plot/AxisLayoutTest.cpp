#include "plot/AxisLayout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace abalike::app
{
namespace
{

constexpr double kInf = std::numeric_limits<double>::infinity();

PlotAxis axis(AxisScale scale)
{
    PlotAxis a;
    a.scale = scale;
    return a;
}

std::vector<std::string> labels(const AxisLayout& layout)
{
    std::vector<std::string> out;
    for (const AxisTick& t : layout.major)
        out.push_back(t.label);
    return out;
}

TEST(AxisLayoutTest, LinearRoundsOutToNiceTicks)
{
    const AxisLayout l = layoutAxis(axis(AxisScale::Linear), 0.3, 9.3);
    EXPECT_EQ(l.lo, 0.0);
    EXPECT_EQ(l.hi, 10.0);
    EXPECT_EQ(labels(l), (std::vector<std::string>{"0", "2", "4", "6", "8", "10"}));
    // Quarters of a step of 2: three minor lines between each pair of majors.
    EXPECT_EQ(l.minor.size(), 15u);
    EXPECT_DOUBLE_EQ(l.minor.front(), 0.5);
}

TEST(AxisLayoutTest, LinearDecimalsFollowTheStepAndNegativesUseAMinusSign)
{
    const AxisLayout l = layoutAxis(axis(AxisScale::Linear), -0.27, 0.04);
    EXPECT_DOUBLE_EQ(l.lo, -0.3);
    EXPECT_DOUBLE_EQ(l.hi, 0.1);
    EXPECT_EQ(labels(l), (std::vector<std::string>{"−0.3", "−0.2", "−0.1", "0.0", "0.1"}));
    const AxisLayout fine = layoutAxis(axis(AxisScale::Linear), 0.0, 0.28);
    EXPECT_EQ(labels(fine), (std::vector<std::string>{"0.00", "0.05", "0.10", "0.15", "0.20", "0.25", "0.30"}));
}

TEST(AxisLayoutTest, FixedEndsAndStepAreKept)
{
    PlotAxis a = axis(AxisScale::Linear);
    a.min = 0.0;
    a.max = 90.0;
    a.tickStep = 15.0;
    const AxisLayout l = layoutAxis(a, 12.0, 70.0);
    EXPECT_EQ(l.lo, 0.0);
    EXPECT_EQ(l.hi, 90.0);
    EXPECT_EQ(labels(l), (std::vector<std::string>{"0", "15", "30", "45", "60", "75", "90"}));
    EXPECT_DOUBLE_EQ(l.fraction(45.0), 0.5);
}

TEST(AxisLayoutTest, OnlyOneEndFixedRoundsTheOther)
{
    PlotAxis a = axis(AxisScale::Linear);
    a.min = 0.0;
    const AxisLayout l = layoutAxis(a, 11.0, 41.3);
    EXPECT_EQ(l.lo, 0.0);
    EXPECT_EQ(l.hi, 50.0);
}

TEST(AxisLayoutTest, AStepFarTooFineIsReplaced)
{
    PlotAxis a = axis(AxisScale::Linear);
    a.tickStep = 1e-9;
    const AxisLayout l = layoutAxis(a, 0.0, 100.0);
    EXPECT_LE(l.major.size(), 12u);
    EXPECT_GE(l.major.size(), 4u);
}

TEST(AxisLayoutTest, DegenerateRangesGetAWidth)
{
    const AxisLayout single = layoutAxis(axis(AxisScale::Linear), 5.0, 5.0);
    EXPECT_LT(single.lo, 5.0);
    EXPECT_GT(single.hi, 5.0);
    const AxisLayout zero = layoutAxis(axis(AxisScale::Linear), 0.0, 0.0);
    EXPECT_LT(zero.lo, 0.0);
    EXPECT_GT(zero.hi, 0.0);
    const AxisLayout none = layoutAxis(axis(AxisScale::Linear), kInf, -kInf);
    EXPECT_EQ(none.lo, 0.0);
    EXPECT_EQ(none.hi, 1.0);
    const AxisLayout logNone = layoutAxis(axis(AxisScale::Log10), kInf, -kInf);
    EXPECT_EQ(logNone.lo, 1.0);
    EXPECT_EQ(logNone.hi, 10.0);
    const AxisLayout logSingle = layoutAxis(axis(AxisScale::Log10), 100.0, 100.0);
    EXPECT_EQ(logSingle.lo, 10.0);
    EXPECT_EQ(logSingle.hi, 1000.0);
}

TEST(AxisLayoutTest, ReversedFixedEndsAreSwapped)
{
    PlotAxis a = axis(AxisScale::Linear);
    a.min = 10.0;
    a.max = -10.0;
    const AxisLayout l = layoutAxis(a, kInf, -kInf);
    EXPECT_EQ(l.lo, -10.0);
    EXPECT_EQ(l.hi, 10.0);
}

TEST(AxisLayoutTest, LogAxesTickAtTheDecades)
{
    const AxisLayout l = layoutAxis(axis(AxisScale::Log10), 1.5e-11, 2.3, 20);
    EXPECT_DOUBLE_EQ(l.lo, 1e-11);
    EXPECT_DOUBLE_EQ(l.hi, 10.0);
    ASSERT_EQ(l.major.size(), 13u);
    EXPECT_EQ(l.major.front().label, "10⁻¹¹");
    EXPECT_EQ(l.major[11].label, "10⁰");
    EXPECT_EQ(l.major.back().label, "10¹");
    EXPECT_EQ(l.minor.size(), 12u * 8u); // 2..9 in each of the 12 decades
    EXPECT_NEAR(l.fraction(1e-5), 0.5, 1e-12);
    EXPECT_FALSE(l.shows(0.0));
    EXPECT_FALSE(l.shows(-1.0));
    EXPECT_FALSE(l.shows(std::nan("")));
    EXPECT_TRUE(l.shows(1e-300));
}

TEST(AxisLayoutTest, ManyDecadesLabelEveryFewSoLabelsStayApart)
{
    const AxisLayout l = layoutAxis(axis(AxisScale::Log10), 1e-14, 1.0, 8);
    ASSERT_EQ(l.major.size(), 15u);
    int labelled = 0;
    for (const AxisTick& t : l.major)
        labelled += t.label.empty() ? 0 : 1;
    EXPECT_LE(labelled, 8);
    EXPECT_GE(labelled, 5);
    EXPECT_EQ(l.major.front().label, "10⁻¹⁴");
}

TEST(AxisLayoutTest, LogAxisWithinADecadeLabelsTheMinorTicks)
{
    PlotAxis a = axis(AxisScale::Log10);
    a.min = 2.0;
    a.max = 9.0;
    const AxisLayout l = layoutAxis(a, 3.0, 7.0);
    EXPECT_EQ(labels(l), (std::vector<std::string>{"2", "3", "4", "5", "6", "7", "8", "9"}));
}

TEST(AxisLayoutTest, HugeRangesStayFinite)
{
    const AxisLayout l = layoutAxis(axis(AxisScale::Log10), 1e-300, 1e300);
    EXPECT_TRUE(l.minor.empty()); // 600 decades: no room for a minor grid
    EXPECT_LE(l.major.size(), 602u);
    const AxisLayout lin = layoutAxis(axis(AxisScale::Linear), -1e300, 1e300);
    EXPECT_TRUE(std::isfinite(lin.lo) && std::isfinite(lin.hi));
    EXPECT_GE(lin.major.size(), 2u);
    const double most = std::numeric_limits<double>::max(), least = std::numeric_limits<double>::denorm_min();
    for (const AxisLayout& extreme :
         {layoutAxis(axis(AxisScale::Linear), -most, most), layoutAxis(axis(AxisScale::Log10), least, most)})
    {
        EXPECT_TRUE(std::isfinite(extreme.lo) && std::isfinite(extreme.hi));
        EXPECT_LT(extreme.lo, extreme.hi);
        EXPECT_TRUE(std::isfinite(extreme.fraction(1.0)));
    }
}

TEST(AxisLayoutTest, Labels)
{
    EXPECT_EQ(decadeLabel(0), "10⁰");
    EXPECT_EQ(decadeLabel(-6), "10⁻⁶");
    EXPECT_EQ(decadeLabel(23), "10²³");
    EXPECT_EQ(tickLabel(-1e-17, 0.1), "0.0");
    EXPECT_EQ(tickLabel(2.5, 0.5), "2.5");
    EXPECT_EQ(tickLabel(-40.0, 20.0), "−40");
}

} // namespace
} // namespace abalike::app

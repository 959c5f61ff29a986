#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/FlightModel.hpp>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>

namespace abalike
{
namespace
{

struct BadModel
{
    const char* name;
    std::function<void(FlightModel&)> spoil;
    const char* mentions;
};

std::ostream& operator<<(std::ostream& out, const BadModel& bad)
{
    return out << bad.name;
}

class InvalidModel : public testing::TestWithParam<BadModel>
{
};

TEST_P(InvalidModel, IsRejectedWithAMessage)
{
    FlightModel model;
    model.quadraticDrag = 0.01;
    GetParam().spoil(model);
    const std::string problem = validateFlightModel(model);
    EXPECT_NE(problem.find(GetParam().mentions), std::string::npos) << problem;
    EXPECT_THROW(FlightIntegrator(model, {}), std::invalid_argument);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(
    Cases, InvalidModel,
    testing::Values(BadModel{"NaNGravity", [](FlightModel& m) { m.gravity = kNaN; }, "gravity"},
                    BadModel{"InfiniteGravity", [](FlightModel& m) { m.gravity = kInf; }, "gravity"},
                    BadModel{"NegativeGravity", [](FlightModel& m) { m.gravity = -1.0; }, "gravity"},
                    BadModel{"ZeroMass", [](FlightModel& m) { m.massKg = 0.0; }, "mass"},
                    BadModel{"NegativeMass", [](FlightModel& m) { m.massKg = -2.0; }, "mass"},
                    BadModel{"NaNMass", [](FlightModel& m) { m.massKg = kNaN; }, "mass"},
                    BadModel{"InfiniteMass", [](FlightModel& m) { m.massKg = kInf; }, "mass"},
                    BadModel{"NegativeLinearDrag", [](FlightModel& m) { m.linearDrag = -0.1; }, "linear drag"},
                    BadModel{"NegativeQuadraticDrag", [](FlightModel& m) { m.quadraticDrag = -0.1; }, "quadratic drag"},
                    BadModel{"MinusInfiniteDrag", [](FlightModel& m) { m.quadraticDrag = -kInf; }, "quadratic drag"},
                    BadModel{"NaNWind", [](FlightModel& m) { m.windX = kNaN; }, "wind"},
                    BadModel{"ZeroGustPeriod",
                             [](FlightModel& m)
                             {
                                 m.gusts = GustDef{};
                                 m.gusts->kind = GustDef::Kind::Sine;
                                 m.gusts->periodS = 0.0;
                             },
                             "gust period"},
                    BadModel{"UnsortedGustSteps",
                             [](FlightModel& m)
                             {
                                 m.gusts = GustDef{};
                                 m.gusts->steps = {{2.0, 1.0, 0.0}, {1.0, 0.0, 0.0}};
                             },
                             "gust step"}),
    [](const testing::TestParamInfo<BadModel>& info) { return std::string(info.param.name); });

TEST(FlightModel, ValidModelsPass)
{
    FlightModel moon;
    moon.gravity = 1.62;
    EXPECT_EQ(validateFlightModel(moon), "");
    FlightModel space;
    space.gravity = 0.0;
    space.massKg = 1e4;
    EXPECT_EQ(validateFlightModel(space), "");
}

TEST(FlightModel, IntegratorRejectsBadSettings)
{
    IntegratorSettings zeroDt;
    zeroDt.dtS = 0.0;
    EXPECT_THROW(FlightIntegrator(FlightModel{}, zeroDt), std::invalid_argument);
    IntegratorSettings nanTol;
    nanTol.tolerance = kNaN;
    EXPECT_THROW(FlightIntegrator(FlightModel{}, nanTol), std::invalid_argument);
}

} // namespace
} // namespace abalike

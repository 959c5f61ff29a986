#include "RunAbalike.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace abalike::test
{
namespace
{

struct BadFlight
{
    const char* name;
    std::string args;
    const char* expectedInMessage;
};

std::ostream& operator<<(std::ostream& out, const BadFlight& bad)
{
    return out << bad.name;
}

class PredictInvalidInput : public ::testing::TestWithParam<BadFlight>
{
};

/// Invalid flight inputs: exit 2, one line on stderr naming the problem, nothing on stdout.
TEST_P(PredictInvalidInput, ExitsTwoWithAMessage)
{
    const BadFlight& bad = GetParam();
    const RunResult r = runAbalike("predict --angle 45 --speed 20 --json " + bad.args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(bad.expectedInMessage), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, PredictInvalidInput,
    ::testing::Values(BadFlight{"NaNMass", "--mass nan", "--mass"}, BadFlight{"InfiniteMass", "--mass inf", "--mass"},
                      BadFlight{"MinusInfiniteMass", "--mass=-inf", "--mass"},
                      BadFlight{"ZeroMass", "--mass 0", "mass must be > 0"},
                      BadFlight{"NegativeMass", "--mass=-1", "mass must be > 0"},
                      BadFlight{"NaNGravity", "--gravity nan", "--gravity"},
                      BadFlight{"InfiniteGravity", "--gravity inf", "--gravity"},
                      BadFlight{"NegativeLinearDrag", "--linear-drag=-0.1", "linear drag must be >= 0"},
                      BadFlight{"NegativeQuadraticDrag", "--quadratic-drag=-0.02", "quadratic drag must be >= 0"},
                      BadFlight{"NaNQuadraticDrag", "--quadratic-drag nan", "--quadratic-drag"},
                      BadFlight{"InfiniteLinearDrag", "--linear-drag inf", "--linear-drag"},
                      BadFlight{"NaNWind", "--quadratic-drag 0.02 --wind nan,0", "--wind"},
                      BadFlight{"InfiniteWind", "--quadratic-drag 0.02 --wind 0,-inf", "--wind"},
                      BadFlight{"NaNAngle", "--angle nan", "--angle"}, BadFlight{"NaNDt", "--dt nan", "--dt"},
                      BadFlight{"InfiniteTol", "--tol inf", "--tol"},
                      BadFlight{"UnknownStepper", "--stepper leapfrog", "unknown stepper \"leapfrog\""},
                      BadFlight{"AnalyticWithQuadraticDrag", "--stepper analytic --quadratic-drag 0.02",
                                "analytic stepper has no closed form"},
                      BadFlight{"AnalyticWithGusts", "--stepper analytic --linear-drag 0.1 --gust-sine 1,0,2",
                                "analytic stepper has no closed form"},
                      BadFlight{"GustSineZeroPeriod", "--quadratic-drag 0.02 --gust-sine 1,0,0", "period"},
                      BadFlight{"GustSineTwoNumbers", "--quadratic-drag 0.02 --gust-sine 1,0", "three numbers"},
                      BadFlight{"GustBothKinds", "--quadratic-drag 0.02 --gust-sine 1,0,2 --gust-step 1,2,0",
                                "cannot be combined"}),
    [](const ::testing::TestParamInfo<BadFlight>& info) { return std::string(info.param.name); });

nlohmann::json predictJson(const std::string& args)
{
    const RunResult r = runAbalike("predict --json " + args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

TEST(PredictCli, TermsListExactlyTheActiveEffects)
{
    EXPECT_EQ(predictJson("--angle 45 --speed 20")["terms"], nlohmann::json({"gravity"}));
    // Wind acts through drag; without drag it is no term.
    EXPECT_EQ(predictJson("--angle 45 --speed 20 --wind 3,0")["terms"], nlohmann::json({"gravity"}));
    EXPECT_EQ(predictJson("--angle 45 --speed 20 --quadratic-drag 0.02 --linear-drag 0.1 --wind 3,0 --gust-sine "
                          "1,0,2")["terms"],
              nlohmann::json({"gravity", "linear_drag", "quadratic_drag", "wind", "gusts"}));
    EXPECT_EQ(predictJson("--angle 45 --speed 20 --gravity 0 --quadratic-drag 0.02 --gust-step 0.5,4,0")["terms"],
              nlohmann::json({"quadratic_drag", "gusts"}));
}

TEST(PredictCli, ReportsWhatTheStiffnessGuardDid)
{
    const std::string stiff = "--angle 45 --speed 50 --mass 0.01 --quadratic-drag 0.05";
    const nlohmann::json guarded = predictJson(stiff);
    EXPECT_EQ(guarded["guard"], "substep");
    EXPECT_GT(guarded["substeps"].get<int>(), 0);
    EXPECT_TRUE(guarded["landed"].get<bool>());
    const nlohmann::json plain = predictJson(stiff + " --no-guard");
    EXPECT_EQ(plain["guard"], "off");
    EXPECT_EQ(plain["substeps"], 0);
    EXPECT_FALSE(plain["landed"].get<bool>()); // it blew up instead
    EXPECT_TRUE(plain["diverged"].get<bool>());
    EXPECT_FALSE(guarded["diverged"].get<bool>());
    EXPECT_EQ(predictJson("--angle 45 --speed 50 --mass 0.0001 --linear-drag 1")["guard"], "rosenbrock4");
    EXPECT_EQ(predictJson("--angle 45 --speed 20")["guard"], "none");
}

} // namespace
} // namespace abalike::test

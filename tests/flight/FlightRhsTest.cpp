#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/FlightRhs.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <type_traits>

namespace abalike
{
namespace
{

FlightModel everything()
{
    FlightModel model;
    model.massKg = 2.0;
    model.linearDrag = 0.4;
    model.quadraticDrag = 0.1;
    model.windX = 3.0;
    model.windY = -1.0;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    gusts.amplitudeX = 2.0;
    gusts.periodS = 4.0;
    model.gusts = gusts;
    return model;
}

TEST(FlightRhs, GravityOnlyIgnoresDragAndWindInTheModel)
{
    // The model has drag and wind, but a gravity-only right-hand side is compiled without them.
    const FlightModel model = everything();
    const FlightRhs<kGravityTerm> rhs(model);
    FlightState dsdt{};
    rhs({{1.0, 2.0}, {30.0, -5.0}}, dsdt, 0.7);
    EXPECT_EQ(dsdt, (FlightState{{30.0, -5.0}, {0.0, -9.81}}));
    EXPECT_EQ(rhs.stiffness({{0, 0}, {30, -5}}, 0.0), 0.0);
    static_assert(!FlightRhs<kGravityTerm>::kHasDrag);
}

TEST(FlightRhs, EachTermAddsItsForce)
{
    const FlightModel model = everything();
    const FlightState s{{0.0, 0.0}, {10.0, 4.0}};
    const double t = 1.0; // sin(2 pi / 4) = 1: the gust is (2, 0)
    FlightState d{};

    FlightRhs<kGravityTerm | kLinearDragTerm>{model}(s, d, t);
    EXPECT_DOUBLE_EQ(d.velocity.x, -0.2 * 10.0);
    EXPECT_DOUBLE_EQ(d.velocity.y, -9.81 - 0.2 * 4.0);

    FlightRhs<kQuadraticDragTerm | kWindTerm>{model}(s, d, t);
    const double rx = 10.0 - 3.0, ry = 4.0 + 1.0;
    const double speed = std::hypot(rx, ry);
    EXPECT_DOUBLE_EQ(d.velocity.x, -0.05 * speed * rx);
    EXPECT_DOUBLE_EQ(d.velocity.y, -0.05 * speed * ry);

    FlightRhs<kQuadraticDragTerm | kWindTerm | kGustTerm>{model}(s, d, t);
    const double gx = 10.0 - 3.0 - 2.0;
    const double gspeed = std::hypot(gx, ry);
    EXPECT_NEAR(d.velocity.x, -0.05 * gspeed * gx, 1e-12);
    EXPECT_NEAR(d.velocity.y, -0.05 * gspeed * ry, 1e-12);
}

TEST(FlightRhs, JacobianMatchesFiniteDifferences)
{
    const FlightModel model = everything();
    const FlightRhs<kAllFlightTerms> rhs(model);
    const FlightState s{{0.0, 0.0}, {12.0, -3.0}};
    const double t = 0.3;
    std::array<double, 4> dadv{};
    Vec2 dadt{};
    rhs.accelerationJacobian(s, t, dadv, dadt);
    const double h = 1e-6;
    for (std::size_t j = 0; j < 2; ++j)
    {
        FlightState a = s, b = s, fa{}, fb{};
        (j == 0 ? a.velocity.x : a.velocity.y) -= h;
        (j == 0 ? b.velocity.x : b.velocity.y) += h;
        rhs(a, fa, t);
        rhs(b, fb, t);
        EXPECT_NEAR(dadv[j], (fb.velocity.x - fa.velocity.x) / (2 * h), 1e-6);
        EXPECT_NEAR(dadv[2 + j], (fb.velocity.y - fa.velocity.y) / (2 * h), 1e-6);
    }
    FlightState fa{}, fb{};
    rhs(s, fa, t - h);
    rhs(s, fb, t + h);
    EXPECT_NEAR(dadt.x, (fb.velocity.x - fa.velocity.x) / (2 * h), 1e-6);
    EXPECT_NEAR(dadt.y, (fb.velocity.y - fa.velocity.y) / (2 * h), 1e-6);
}

TEST(FlightTerms, ActiveTermsAreOnlyTheOnesThatActUp)
{
    FlightModel model;
    EXPECT_EQ(activeTerms(model), kGravityTerm);
    model.gravity = 0.0;
    EXPECT_EQ(activeTerms(model), 0u);
    model.windX = 5.0; // wind acts only through drag: without drag it is not a term
    model.gusts = GustDef{};
    EXPECT_EQ(activeTerms(model), 0u);
    model.quadraticDrag = 0.01;
    EXPECT_EQ(activeTerms(model), kQuadraticDragTerm | kWindTerm | kGustTerm);
    model.linearDrag = 0.1;
    model.gravity = 1.62;
    EXPECT_EQ(activeTerms(model), kAllFlightTerms);
}

TEST(FlightTerms, NamesInFixedOrder)
{
    EXPECT_EQ(termNames(kAllFlightTerms),
              (std::vector<std::string>{"gravity", "linear_drag", "quadratic_drag", "wind", "gusts"}));
    EXPECT_EQ(termNames(kWindTerm | kGravityTerm), (std::vector<std::string>{"gravity", "wind"}));
    EXPECT_TRUE(termNames(0).empty());
}

TEST(FlightTerms, VisitComposesTheActiveTerms)
{
    FlightModel model;
    model.windX = 4.0; // inactive without drag
    const unsigned terms = visitFlightRhs(model, [](auto rhs) { return decltype(rhs)::kTerms; });
    EXPECT_EQ(terms, kGravityTerm);
    model.quadraticDrag = 0.02;
    EXPECT_EQ(visitFlightRhs(model, [](auto rhs) { return decltype(rhs)::kTerms; }),
              kGravityTerm | kQuadraticDragTerm | kWindTerm);
}

TEST(Gusts, StepsHoldUntilTheNextStep)
{
    GustDef gusts;
    gusts.steps = {{1.0, 2.0, 0.0}, {3.0, -1.0, 0.5}};
    EXPECT_EQ(gusts.windAt(0.5), (Vec2{0.0, 0.0}));
    EXPECT_EQ(gusts.windAt(1.0), (Vec2{2.0, 0.0}));
    EXPECT_EQ(gusts.windAt(2.9), (Vec2{2.0, 0.0}));
    EXPECT_EQ(gusts.windAt(10.0), (Vec2{-1.0, 0.5}));
    EXPECT_EQ(gusts.rateAt(2.0), (Vec2{0.0, 0.0}));
}

TEST(Gusts, SineAndItsRate)
{
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    gusts.amplitudeX = 2.0;
    gusts.amplitudeY = -1.0;
    gusts.periodS = 2.0;
    EXPECT_NEAR(gusts.windAt(0.5).x, 2.0, 1e-15);
    EXPECT_NEAR(gusts.windAt(0.5).y, -1.0, 1e-15);
    EXPECT_NEAR(gusts.rateAt(0.0).x, 2.0 * M_PI, 1e-12);
}

TEST(Gusts, FixedStepsStopAtAGustStepSoRk4KeepsItsOrder)
{
    // A gust that switches on at t = 0.51 s, inside a 1/60 s step: RK4 ends a sub-step there. Halving dt must
    // still shrink the error about 16-fold, as it would without the jump.
    FlightModel model;
    model.quadraticDrag = 0.05;
    model.gusts = GustDef{};
    model.gusts->steps = {{0.51, 8.0, 0.0}};
    auto endAt = [&](double dt, StepperKind stepper, double tol)
    {
        IntegratorSettings settings;
        settings.stepper = stepper;
        settings.dtS = dt;
        settings.tolerance = tol;
        FlightIntegrator integrator(model, settings);
        integrator.reset(0.0, launchState(0, 0, 20, 45));
        const int steps = static_cast<int>(std::lround(1.2 / dt));
        for (int i = 0; i < steps; ++i)
            integrator.step();
        return integrator.state();
    };
    const FlightState reference = endAt(0.01, StepperKind::Dopri5, 1e-13);
    const FlightState coarse = endAt(0.04, StepperKind::Rk4, 1e-9);
    const FlightState fine = endAt(0.02, StepperKind::Rk4, 1e-9);
    const double ratio =
        std::hypot(coarse.position.x - reference.position.x, coarse.position.y - reference.position.y) /
        std::hypot(fine.position.x - reference.position.x, fine.position.y - reference.position.y);
    EXPECT_GT(ratio, 12.0);
}

} // namespace
} // namespace abalike

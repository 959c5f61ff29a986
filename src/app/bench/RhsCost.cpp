#include "bench/RhsCost.hpp"
#include <abalike/util/MedianTimer.hpp>

#include <abalike/flight/FlightRhs.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/game/ReferenceShots.hpp>

#include <benchmark/benchmark.h>
#include <cmath>

namespace abalike::app
{

namespace
{

/// The naive alternative to FlightRhs: one function for every scene that asks, on every call, which terms exist.
class BranchingRhs
{
public:
    explicit BranchingRhs(const FlightModel& model) : m_model(model) {}

    void operator()(const FlightState& s, FlightState& dsdt, double t) const
    {
        dsdt.position.x = s.velocity.x;
        dsdt.position.y = s.velocity.y;
        double ax = 0.0;
        double ay = -m_model.gravity;
        if (m_model.linearDrag != 0.0 || m_model.quadraticDrag != 0.0)
        {
            double rx = s.velocity.x - m_model.windX;
            double ry = s.velocity.y - m_model.windY;
            if (m_model.gusts)
            {
                const auto gust = m_model.gusts->windAt(t);
                rx -= gust.x;
                ry -= gust.y;
            }
            const double k =
                (m_model.linearDrag + m_model.quadraticDrag * std::sqrt(rx * rx + ry * ry)) / m_model.massKg;
            ax -= k * rx;
            ay -= k * ry;
        }
        dsdt.velocity.x = ax;
        dsdt.velocity.y = ay;
    }

private:
    FlightModel m_model;
};

/// Median nanoseconds per call of rhs over a batch of varied states.
template <class Rhs>
double nsPerEvaluation(const Rhs& rhs, bool quick)
{
    std::vector<FlightState> states;
    for (int i = 0; i < 1024; ++i)
        states.push_back({{0.1 * i, 0.05 * i}, {30.0 * std::cos(0.01 * i), 25.0 * std::sin(0.013 * i)}});
    auto sweep = [&]
    {
        FlightState dsdt{};
        double t = 0.0;
        for (const FlightState& s : states)
        {
            rhs(s, dsdt, t);
            benchmark::DoNotOptimize(dsdt);
            t += 1e-3;
        }
    };
    return 1e9 * medianSeconds(sweep, quick ? 9 : 41, 20) / static_cast<double>(states.size());
}

struct FlightScene
{
    const char* name;
    FlightModel model;
    ReferenceShot shot;
};

std::vector<FlightScene> scenes()
{
    const ReferenceShot base{.name = "cost", .description = "", .angleDeg = 50.0, .speedMps = 30.0, .wallX = 60.0};
    std::vector<FlightScene> list;
    list.push_back({"gravity only (vacuum)", FlightModel{}, base});

    FlightScene windy{"gravity + quadratic drag + wind", FlightModel{}, base};
    windy.model.massKg = 4.0;
    windy.model.quadraticDrag = quadraticDragCoefficient(1.2, 0.47, 0.25);
    windy.model.windX = -6.0;
    windy.model.windY = 1.5;
    windy.shot.airDensity = 1.2;
    windy.shot.windX = -6.0;
    windy.shot.windY = 1.5;
    list.push_back(windy);

    FlightScene all = windy;
    all.name = "all terms (+ linear drag, sine gusts)";
    all.model.linearDrag = 0.2;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    gusts.amplitudeX = 4.0;
    gusts.periodS = 1.5;
    all.model.gusts = gusts;
    all.shot.gusts = gusts; // the level has no linear drag; its preview row shows drag, wind and gusts
    list.push_back(all);
    return list;
}

} // namespace

std::vector<RhsCost> measureRhsCost(bool quick)
{
    std::vector<RhsCost> rows;
    for (const FlightScene& scene : scenes())
    {
        RhsCost row;
        row.scene = scene.name;
        for (const std::string& name : termNames(activeTerms(scene.model)))
            row.terms += (row.terms.empty() ? "" : " ") + name;
        row.composedNs = visitFlightRhs(scene.model, [&](auto rhs) { return nsPerEvaluation(rhs, quick); });
        row.branchingNs = nsPerEvaluation(BranchingRhs(scene.model), quick);

        PredictionLimits limits;
        limits.stopOnLanding = true;
        const FlightState launch = launchState(0.0, 1.5, 30.0, 50.0);
        row.previewSteps = predictFlight(scene.model, {}, launch, limits).steps;
        row.previewUs =
            1e6 * medianSeconds([&] { benchmark::DoNotOptimize(predictFlight(scene.model, {}, launch, limits)); },
                                quick ? 9 : 41, 20);

        const GameSession session(referenceShotLevel(scene.shot));
        row.sessionPreviewUs =
            1e6 * medianSeconds([&] { benchmark::DoNotOptimize(session.preview(scene.shot.angleDeg, 30.0)); },
                                quick ? 9 : 41, 10);
        rows.push_back(row);
    }
    return rows;
}

} // namespace abalike::app

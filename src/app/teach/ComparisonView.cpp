#include "teach/ComparisonView.hpp"

#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <array>
#include <cmath>
#include <cstdio>

namespace abalike::app
{

namespace
{

constexpr std::array<StepperKind, 4> kMethods{StepperKind::Euler, StepperKind::SemiImplicitEuler, StepperKind::Rk4,
                                              StepperKind::Dopri5};
/// Steps per second the fixed-step methods can use: 1/15 s to 1/240 s.
constexpr std::array<int, 6> kRates{15, 20, 30, 60, 120, 240};
constexpr std::array<double, 6> kTolerances{1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
constexpr double kPhysicsDtS = 1.0 / 60.0;

} // namespace

ComparisonMethod ComparisonView::method() const
{
    ComparisonMethod m;
    m.stepper = kMethods[static_cast<std::size_t>(std::max(0, m_method - 1)) % kMethods.size()];
    m.dtS = 1.0 / kRates[static_cast<std::size_t>(m_stepIndex)];
    m.tolerance = kTolerances[static_cast<std::size_t>(m_stepIndex)];
    return m;
}

bool ComparisonView::handleKey(const sf::Event::KeyEvent& key)
{
    if (key.code == sf::Keyboard::I)
    {
        m_method = (m_method + 1) % static_cast<int>(kMethods.size() + 1);
        m_dirty = true;
        return true;
    }
    if (!active())
        return false;
    if (key.code == sf::Keyboard::LBracket || key.code == sf::Keyboard::RBracket)
    {
        const int delta = key.code == sf::Keyboard::RBracket ? 1 : -1;
        m_stepIndex = std::clamp(m_stepIndex + delta, 0, static_cast<int>(kRates.size()) - 1);
        m_dirty = true;
        return true;
    }
    return false;
}

void ComparisonView::update(const GameSession& session, const PredictedFlight* preview)
{
    if (!active() || preview == nullptr || preview->path.empty() || session.currentBird() == nullptr)
    {
        m_result.reset();
        m_lastPreview = nullptr;
        return;
    }
    // The play screen replaces its preview whenever the aim changes; its end point tells a new one from the old.
    const PathPoint& end = preview->path.back();
    const bool same = m_lastPreview == preview && m_lastPreviewSteps == preview->path.size() && m_lastPreviewEnd &&
                      m_lastPreviewEnd->timeS == end.timeS && m_lastPreviewEnd->state == end.state;
    if (same && !m_dirty)
        return;
    m_dirty = false;
    m_lastPreview = preview;
    m_lastPreviewSteps = preview->path.size();
    m_lastPreviewEnd = end;

    const BirdType& bird = *session.currentBird();
    const FlightModel model = session.flightModelFor(bird);
    const FlightState s0 = preview->path.front().state;
    PredictionLimits limits;
    limits.maxTimeS = 15.0; // as GameSession::preview
    const GameWorld& world = session.world();
    const double radius = bird.radiusM;
    limits.contact = [&world, radius](const FlightState& a, const FlightState& b)
    {
        return world.castCircle(radius, a, b);
    };
    try
    {
        m_result = compareIntegrator(model, s0, method(), kPhysicsDtS, *preview, limits, ComparisonCost::Measure);
        m_realEvaluations = preview->rhsEvaluations;
    }
    catch (const std::exception&)
    {
        m_result.reset(); // a method that cannot fly this launch is simply not drawn
    }
}

void ComparisonView::drawWorld(sf::RenderTarget& target, const Camera& camera, float scale) const
{
    if (!m_result)
        return;
    Mesh mesh;
    std::vector<sf::Vector2f> line;
    for (const PathPoint& p : m_result->flight.path)
        line.push_back(
            camera.toScreen({static_cast<float>(p.state.position.x), static_cast<float>(p.state.position.y)}));
    mesh.addPolyline(line, 2.5f * scale, faded(teach::kComparison, 0.85f));
    for (const sf::Vector2f& p : line)
        mesh.addCircle(p, 2.6f * scale, teach::kComparison, 10);
    if (m_result->flight.contact)
        mesh.addRing(camera.toScreen({static_cast<float>(m_result->flight.contact->x),
                                      static_cast<float>(m_result->flight.contact->y)}),
                     8.0f * scale, 2.5f * scale, teach::kComparison);
    mesh.draw(target);
}

sf::FloatRect ComparisonView::drawPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                                        unsigned titleSize, unsigned rowSize, float scale) const
{
    if (!active())
        return {};
    std::vector<PanelRow> rows;
    rows.push_back({method().label(), "", teach::kComparison});
    if (m_result)
    {
        rows.push_back({"largest error against the real path", formatDistance(m_result->maxErrorM)});
        if (m_result->contactErrorM)
            rows.push_back({"first contact off by", formatDistance(*m_result->contactErrorM)});
        else if (!m_result->flight.contact)
            rows.push_back({"first contact", "none within 15 s"});
        char cost[96];
        std::snprintf(cost, sizeof cost, "%.1f \u00B5s (%zu force evaluations)", m_result->costUs.value_or(0.0),
                      m_result->flight.rhsEvaluations);
        rows.push_back({"cost", cost});
        std::snprintf(cost, sizeof cost, "%.1f \u00B5s (%zu)", m_result->realCostUs.value_or(0.0), m_realEvaluations);
        rows.push_back({"the real preview: RK4 at 1/60 s", cost});
    }
    else
        rows.push_back({"aim to compare it with the preview", ""});
    rows.push_back(
        {"I: next method   [ ]: " + std::string(method().stepper == StepperKind::Dopri5 ? "looser / tighter tolerance"
                                                                                        : "longer / shorter step"),
         ""});
    const TextPanel panel("Integrator comparison", std::move(rows));
    const sf::Vector2f size = panel.measure(font, titleSize, rowSize, scale);
    return panel.draw(target, font, {topRight.x - size.x, topRight.y}, titleSize, rowSize, scale);
}

} // namespace abalike::app

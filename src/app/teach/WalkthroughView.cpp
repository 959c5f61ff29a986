#include "teach/WalkthroughView.hpp"

#include "render/Label.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "shell/AppContext.hpp"
#include "shell/Notices.hpp"
#include "teach/TeachDraw.hpp"

#include <abalike/flight/ClosedForm.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace abalike::app
{

namespace
{

/// Step sizes to choose from: the physics step, and larger ones that make the four slopes easy to tell apart.
constexpr std::array<double, 5> kSteps{1.0 / 60.0, 0.1, 0.25, 0.5, 1.0};
const sf::Color kStageColours[] = {{86, 180, 233}, {0, 200, 140}, {240, 160, 40}, {220, 120, 230}};
const sf::Color kAverage(255, 230, 80);

sf::Vector2f position(const FlightState& s)
{
    return {static_cast<float>(s.position.x), static_cast<float>(s.position.y)};
}

std::string pair(double a, double b, int decimals)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%.*f, %.*f)", decimals, a, decimals, b);
    return text;
}

std::string stepLabel(double dt)
{
    return dt < 0.02 ? std::string("1/60 s") : formatFixed(dt, 2) + " s";
}

/// Points of the true path over the step: RK4 at a fiftieth of it, as good as exact at this scale.
std::vector<FlightState> finePath(const FlightModel& model, double t0, const FlightState& s0, double dt)
{
    IntegratorSettings settings;
    settings.dtS = dt / 50.0;
    FlightIntegrator integrator(model, settings);
    integrator.reset(t0, s0);
    std::vector<FlightState> points{s0};
    for (int i = 0; i < 50; ++i)
        points.push_back(integrator.step().s1);
    return points;
}

} // namespace

bool WalkthroughView::handleEvent(const sf::Event& event, PlayView& view, ShotFollower& follower)
{
    if (event.type != sf::Event::KeyPressed)
        return active() && (event.type == sf::Event::MouseButtonPressed || event.type == sf::Event::KeyReleased);
    const sf::Keyboard::Key key = event.key.code;
    if (!active())
    {
        if (key != sf::Keyboard::K)
            return false;
        start(view, follower);
        return true;
    }
    switch (key)
    {
    case sf::Keyboard::K:
    case sf::Keyboard::Escape:
        stop(view);
        break;
    case sf::Keyboard::Space:
    case sf::Keyboard::Enter:
    case sf::Keyboard::Right:
    case sf::Keyboard::Period:
        next(view);
        break;
    case sf::Keyboard::LBracket:
    case sf::Keyboard::RBracket:
        m_dtIndex =
            std::clamp(m_dtIndex + (key == sf::Keyboard::RBracket ? 1 : -1), 0, static_cast<int>(kSteps.size()) - 1);
        m_followsWorld = m_followsWorld && m_dtIndex == 0;
        recompute();
        break;
    default:
        break;
    }
    return true; // while it runs, the keys are its own
}

void WalkthroughView::start(PlayView& view, ShotFollower& follower)
{
    const GameSession& session = view.session();
    if (const std::optional<BirdReadout> bird = follower.current(session))
    {
        // Mid-flight: from where the world's bird is now, on its RK4 path.
        m_model = *follower.model();
        m_tS = bird->tS;
        m_state = bird->state;
        m_followsWorld = m_dtIndex == 0;
    }
    else if (const PredictedFlight* preview = view.preview();
             preview != nullptr && !preview->path.empty() && session.currentBird() != nullptr)
    {
        // At launch: from the slingshot with the current aim.
        m_model = session.flightModelFor(*session.currentBird());
        m_tS = 0.0;
        m_state = preview->path.front().state;
        m_followsWorld = false;
    }
    else
    {
        view.app().notices().notify("The RK4 walkthrough needs a bird in free flight or one being aimed.");
        return;
    }
    view.setFrozen(true);
    m_stepNumber = 1;
    m_chain.assign(1, m_state);
    recompute();
}

void WalkthroughView::stop(PlayView& view)
{
    if (!m_walk)
        return;
    m_walk.reset();
    m_chain.clear();
    view.setFrozen(false);
}

void WalkthroughView::recompute()
{
    try
    {
        m_walk = walkRk4Step(m_model, m_tS, m_state, kSteps[static_cast<std::size_t>(m_dtIndex)]);
    }
    catch (const std::exception&)
    {
        m_walk.reset();
    }
}

void WalkthroughView::next(PlayView& view)
{
    if (!m_walk)
        return;
    if (m_followsWorld && view.session().world().birdInFreeFlight())
        view.stepOnce(); // the world's bird takes the very same RK4 step
    else
        m_followsWorld = false;
    m_state = m_walk->next;
    m_tS += m_walk->dtS;
    m_chain.push_back(m_state);
    ++m_stepNumber;
    recompute();
}

void WalkthroughView::drawWorld(sf::RenderTarget& target, const Camera& camera, float scale) const
{
    if (!m_walk)
        return;
    Mesh mesh;
    std::vector<sf::Vector2f> chain;
    for (const FlightState& s : m_chain)
        chain.push_back(camera.toScreen(position(s)));
    mesh.addPolyline(chain, 2.0f * scale, faded(kAverage, 0.7f));
    for (const sf::Vector2f& p : chain)
        mesh.addCircle(p, 3.5f * scale, kAverage, 12);
    const double dt = m_walk->dtS;
    for (std::size_t i = 0; i < 4; ++i)
    {
        const Rk4Stage& stage = m_walk->stages[i];
        const sf::Vector2f from = camera.toScreen(position(stage.at));
        const sf::Vector2f to = camera.toScreen(position(
            {{stage.at.position.x + dt * stage.slope.position.x, stage.at.position.y + dt * stage.slope.position.y},
             {0.0, 0.0}}));
        addArrow(mesh, from, to, 2.0f * scale, kStageColours[i]);
        mesh.addCircle(from, 3.0f * scale, kStageColours[i], 10);
    }
    addArrow(mesh, camera.toScreen(position(m_walk->state)), camera.toScreen(position(m_walk->next)), 3.0f * scale,
             kAverage);
    mesh.draw(target);
}

void WalkthroughView::drawPanel(sf::RenderTarget& target, const sf::Font& font, float top, unsigned titleSize,
                                unsigned rowSize, float scale) const
{
    if (!m_walk)
        return;
    const Rk4Walkthrough& w = *m_walk;
    std::vector<PanelRow> rows;
    rows.push_back(
        {"slope k = f(t, state):", "(dx/dt, dy/dt) m/s    (dvx/dt, dvy/dt) m/s\u00B2", sf::Color::Transparent});
    static const char* const kNames[] = {"k1 = f(t, s)", "k2 = f(t + dt/2, s + dt/2 k1)",
                                         "k3 = f(t + dt/2, s + dt/2 k2)", "k4 = f(t + dt, s + dt k3)"};
    for (std::size_t i = 0; i < 4; ++i)
        rows.push_back({kNames[i],
                        pair(w.stages[i].slope.position.x, w.stages[i].slope.position.y, 3) + "   " +
                            pair(w.stages[i].slope.velocity.x, w.stages[i].slope.velocity.y, 3),
                        kStageColours[i]});
    rows.push_back({"average (k1 + 2 k2 + 2 k3 + k4) / 6",
                    pair(w.averageSlope.position.x, w.averageSlope.position.y, 3) + "   " +
                        pair(w.averageSlope.velocity.x, w.averageSlope.velocity.y, 3),
                    kAverage});
    rows.push_back({"state s (x, y) m   (vx, vy) m/s", pair(w.state.position.x, w.state.position.y, 3) + "   " +
                                                           pair(w.state.velocity.x, w.state.velocity.y, 3)});
    rows.push_back({"next = s + dt \u00D7 average", pair(w.next.position.x, w.next.position.y, 3) + "   " +
                                                        pair(w.next.velocity.x, w.next.velocity.y, 3)});
    if (w.exact)
    {
        const double error =
            std::hypot(w.next.position.x - (*w.exact).position.x, w.next.position.y - (*w.exact).position.y);
        rows.push_back({"exact (closed form): position off by", formatDistance(error)});
    }
    else
        rows.push_back({"quadratic drag has no closed form: compare the thin true path", ""});
    rows.push_back({std::string(m_followsWorld ? "the bird in the world takes this same step"
                                               : "a ghost flight: the world waits") +
                        "   Space: next step   [ ]: step size   K or Esc: leave",
                    ""});
    const TextPanel panel("RK4 walkthrough \u2014 step " + std::to_string(m_stepNumber) +
                              ", t = " + formatFixed(w.t0S, 3) + " s \u2192 " + formatFixed(w.t0S + w.dtS, 3) +
                              " s, dt = " + stepLabel(w.dtS),
                          std::move(rows));
    const sf::Vector2f size = panel.measure(font, titleSize, rowSize, scale);
    const float insetWidth = 230.0f * scale;
    const float window = static_cast<float>(target.getSize().x);
    const float left = std::max(4.0f, 0.5f * (window - size.x - insetWidth));
    const sf::FloatRect rect = panel.draw(target, font, {left, top}, titleSize, rowSize, scale);

    // The step magnified: where each slope is evaluated, the slope times dt from there, and the true path.
    const sf::FloatRect inset(rect.left + rect.width + 4.0f * scale, rect.top, insetWidth, rect.height);
    drawTeachPanel(target, inset, scale, "walkthrough");
    std::vector<sf::Vector2f> points;
    const double dt = w.dtS;
    for (const Rk4Stage& stage : w.stages)
    {
        points.push_back(position(stage.at));
        points.push_back(position(
            {{stage.at.position.x + dt * stage.slope.position.x, stage.at.position.y + dt * stage.slope.position.y},
             {0, 0}}));
    }
    points.push_back(position(w.next));
    const std::vector<FlightState> truth = finePath(m_model, w.t0S, w.state, dt);
    for (const FlightState& s : truth)
        points.push_back(position(s));
    sf::Vector2f lo = points.front();
    sf::Vector2f hi = points.front();
    for (const sf::Vector2f& p : points)
    {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const float margin = 18.0f * scale;
    const float span = std::max({hi.x - lo.x, hi.y - lo.y, 1e-6f});
    const float pxPerM = std::min((inset.width - 2.0f * margin) / std::max(hi.x - lo.x, 1e-6f * span),
                                  (inset.height - 2.0f * margin - 20.0f * scale) / std::max(hi.y - lo.y, 1e-6f * span));
    const sf::Vector2f centre(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y));
    const sf::Vector2f insetCentre(inset.left + 0.5f * inset.width, inset.top + 0.5f * inset.height + 8.0f * scale);
    const auto toInset = [&](sf::Vector2f p)
    {
        return insetCentre + sf::Vector2f((p.x - centre.x) * pxPerM, -(p.y - centre.y) * pxPerM);
    };
    Mesh mesh;
    std::vector<sf::Vector2f> curve;
    for (const FlightState& s : truth)
        curve.push_back(toInset(position(s)));
    mesh.addPolyline(curve, 1.5f * scale, palette::kTextDim);
    for (std::size_t i = 0; i < 4; ++i)
    {
        const sf::Vector2f from = toInset(points[2 * i]);
        addArrow(mesh, from, toInset(points[2 * i + 1]), 2.0f * scale, kStageColours[i]);
        mesh.addCircle(from, 3.5f * scale, kStageColours[i], 12);
    }
    addArrow(mesh, toInset(position(w.state)), toInset(position(w.next)), 3.0f * scale, kAverage);
    mesh.draw(target);
    drawLabel(target, font, utf8("magnified: dt \u00D7 k from each point"),
              {inset.left + 0.5f * inset.width, inset.top + 4.0f * scale}, rowSize, palette::kTextDim, Align::Centre);
    static const char* const kLabels[] = {"k1", "k2", "k3", "k4"};
    LabelPlacer labels;
    for (std::size_t i = 0; i < 4; ++i)
        labels.draw(target, font, kLabels[i], toInset(points[2 * i + 1]) + sf::Vector2f(4.0f * scale, 0.0f), false,
                    rowSize, kStageColours[i]);
}

} // namespace abalike::app

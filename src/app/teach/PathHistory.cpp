#include "teach/PathHistory.hpp"

#include "render/Label.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{

/// PhET's convention: a small dot every 0.1 s, a large one every second.
constexpr double kDotStepS = 0.1;
constexpr int kDotsPerSecond = 10;
/// How near (pixels at scale 1) the mouse must be to a path point to read it.
constexpr float kPickRadiusPx = 10.0f;

PathSample interpolate(const PathSample& a, const PathSample& b, double t)
{
    const double u = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0.0;
    return {t, a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.vx + u * (b.vx - a.vx), a.vy + u * (b.vy - a.vy)};
}

sf::Vector2f worldOf(const PathSample& s)
{
    return {static_cast<float>(s.x), static_cast<float>(s.y)};
}

float distance(sf::Vector2f a, sf::Vector2f b)
{
    return std::hypot(a.x - b.x, a.y - b.y);
}

} // namespace

void PathHistory::onLevelStart()
{
    m_hover.reset();
    m_pinned = false;
    m_keyPath.reset();
}

void PathHistory::clear()
{
    m_keyPath.reset();
    m_keyTape = false;
    m_hover.reset();
    m_pinned = false;
    m_tape.reset();
    m_taping = false;
}

void PathHistory::drawDots(sf::RenderTarget& target, const ShotTrails& trails, const Camera& camera, float scale)
{
    const std::deque<MeasuredPath>& paths = trails.paths();
    Mesh mesh;
    for (std::size_t p = 0; p < paths.size(); ++p)
    {
        const MeasuredPath& path = paths[p];
        if (path.samples.size() < 2)
            continue;
        // Older paths fade so the newest reads first.
        const float age = static_cast<float>(paths.size() - 1 - p);
        const sf::Color colour = faded(path.colour, 1.0f - 0.15f * age);
        const sf::Color rim = faded(palette::kPreviewOutline, 1.0f - 0.15f * age);
        std::vector<sf::Vector2f> line;
        for (const PathSample& s : path.samples)
            line.push_back(camera.toScreen(worldOf(s)));
        mesh.addPolyline(line, 1.5f * scale, faded(colour, 0.6f));
        std::size_t i = 0;
        for (int k = 1;; ++k)
        {
            const double t = k * kDotStepS;
            while (i + 1 < path.samples.size() && path.samples[i + 1].t < t)
                ++i;
            if (i + 1 >= path.samples.size())
                break;
            const sf::Vector2f at = camera.toScreen(worldOf(interpolate(path.samples[i], path.samples[i + 1], t)));
            const bool second = k % kDotsPerSecond == 0;
            const float r = (second ? 4.5f : 2.2f) * scale;
            mesh.addCircle(at, r + 1.0f * scale, rim, 12);
            mesh.addCircle(at, r, colour, 12);
        }
    }
    mesh.draw(target);
}

std::optional<PathHistory::Pick> PathHistory::pick(sf::Vector2f pixel, const PlayView& view, float radiusPx)
{
    const Camera& camera = view.camera();
    std::optional<Pick> best;
    float bestDistance = radiusPx;
    const auto consider = [&](const std::string& name, const PathSample& s)
    {
        const float d = distance(camera.toScreen(worldOf(s)), pixel);
        if (d <= bestDistance)
        {
            bestDistance = d;
            best = Pick{name, s};
        }
    };
    for (const MeasuredPath& path : view.trails().paths())
        for (const PathSample& s : path.samples)
            consider(path.name, s);
    if (const PredictedFlight* preview = view.preview(); preview != nullptr)
        for (const PathPoint& p : preview->path)
            consider("preview",
                     {p.timeS, p.state.position.x, p.state.position.y, p.state.velocity.x, p.state.velocity.y});
    return best;
}

sf::Vector2f PathHistory::snap(sf::Vector2f pixel, const PlayView& view)
{
    if (const std::optional<Pick> near = pick(pixel, view, kPickRadiusPx))
        return worldOf(near->sample);
    return view.camera().toWorld(pixel);
}

void PathHistory::pinOnPath(const PlayView& view, std::size_t fromNewest, double t)
{
    const std::deque<MeasuredPath>& paths = view.trails().paths();
    if (fromNewest >= paths.size() || paths[paths.size() - 1 - fromNewest].samples.empty())
    {
        m_keyPath.reset();
        m_keyTape = false;
        m_hover.reset();
        m_pinned = false;
        return;
    }
    const MeasuredPath& path = paths[paths.size() - 1 - fromNewest];
    const std::vector<PathSample>& samples = path.samples;
    m_keyT = std::clamp(t, samples.front().t, samples.back().t);
    std::size_t i = 0;
    while (i + 2 < samples.size() && samples[i + 1].t < m_keyT)
        ++i;
    const PathSample at = samples.size() < 2 ? samples.front() : interpolate(samples[i], samples[i + 1], m_keyT);
    m_keyPath = fromNewest;
    m_hover = Pick{path.name, at};
    m_pinned = true;
    m_used = true;
    if (m_keyTape && m_tape)
        (*m_tape)[1] = worldOf(at);
}

bool PathHistory::handleKey(const sf::Event::KeyEvent& key, const PlayView& view)
{
    const double stepS = key.shift ? 1.0 : kDotStepS;
    switch (key.code)
    {
    case sf::Keyboard::M:
        pinOnPath(view, m_keyPath ? *m_keyPath + 1 : 0, 0.0);
        return true;
    case sf::Keyboard::Comma:
    case sf::Keyboard::Period:
        if (!m_keyPath)
            return false;
        pinOnPath(view, *m_keyPath, m_keyT + (key.code == sf::Keyboard::Period ? stepS : -stepS));
        return true;
    case sf::Keyboard::L:
        if (m_keyTape || !m_hover)
        {
            m_tape.reset();
            m_keyTape = false;
        }
        else
        {
            const sf::Vector2f start = worldOf(m_hover->sample);
            m_tape = std::array<sf::Vector2f, 2>{start, start};
            m_keyTape = true;
        }
        return true;
    default:
        return false;
    }
}

bool PathHistory::handleEvent(const sf::Event& event, const PlayView& view)
{
    const Camera& camera = view.camera();
    const GameSession& session = view.session();
    if (event.type == sf::Event::MouseMoved)
    {
        const sf::Vector2f pixel(static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y));
        if (m_taping && m_tape)
            (*m_tape)[1] = snap(pixel, view);
        if (!m_pinned)
            m_hover = pick(pixel, view, kPickRadiusPx);
        m_used = m_used || m_hover.has_value();
        return false; // aiming follows the mouse too
    }
    if (event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Right)
    {
        const sf::Vector2f pixel(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
        const sf::Vector2f start = snap(pixel, view);
        m_tape = std::array<sf::Vector2f, 2>{start, start};
        m_taping = true;
        m_used = true;
        return true;
    }
    if (event.type == sf::Event::MouseButtonReleased && event.mouseButton.button == sf::Mouse::Right && m_taping)
    {
        m_taping = false;
        return true;
    }
    // A left click pins a reading, but only while no bird flies (then a click is the bird's ability) and not on the
    // bird in the slingshot, which the player drags to aim.
    if (event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left &&
        session.phase() != Phase::Flying)
    {
        const sf::Vector2f pixel(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
        const auto launch = session.launchPoint();
        const sf::Vector2f sling = camera.toScreen({static_cast<float>(launch.x), static_cast<float>(launch.y)});
        if (distance(pixel, sling) < 40.0f)
            return false;
        if (const std::optional<Pick> hit = pick(pixel, view, kPickRadiusPx))
        {
            m_hover = hit;
            m_pinned = true;
            return true;
        }
        if (m_pinned)
        {
            m_pinned = false; // a click elsewhere lets go
            m_hover.reset();
            return true;
        }
    }
    return false;
}

void PathHistory::drawTools(sf::RenderTarget& target, const sf::Font& font, const Camera& camera,
                            const GameSession& session, unsigned rowSize, float scale) const
{
    Mesh mesh;
    if (m_tape)
    {
        const sf::Vector2f a = camera.toScreen((*m_tape)[0]);
        const sf::Vector2f b = camera.toScreen((*m_tape)[1]);
        mesh.addLine(a, b, 4.0f * scale, sf::Color(250, 210, 60));
        // Tick marks every metre along the tape, as on a real one.
        const sf::Vector2f d = (*m_tape)[1] - (*m_tape)[0];
        const float metres = std::hypot(d.x, d.y);
        const sf::Vector2f n = metres > 0.0f ? sf::Vector2f(-d.y, d.x) / metres : sf::Vector2f(0.0f, 0.0f);
        for (int m = 1; m < metres && m < 500; ++m)
        {
            const sf::Vector2f p = (*m_tape)[0] + (static_cast<float>(m) / metres) * d;
            const float tick = (m % 5 == 0 ? 7.0f : 4.0f) * scale * camera.metresPerPixel();
            mesh.addLine(camera.toScreen(p - tick * n), camera.toScreen(p + tick * n), 1.5f * scale,
                         sf::Color(60, 40, 10));
        }
        mesh.addCircle(a, 4.0f * scale, sf::Color(60, 40, 10));
        mesh.addCircle(b, 4.0f * scale, sf::Color(60, 40, 10));
    }
    if (m_hover)
        mesh.addRing(camera.toScreen(worldOf(m_hover->sample)), 7.0f * scale, 2.0f * scale, palette::kText);
    mesh.draw(target);

    if (m_tape)
    {
        const sf::Vector2f d = (*m_tape)[1] - (*m_tape)[0];
        const std::string text = "tape " + withUnit(std::hypot(d.x, d.y), 2, "m") + "   \u0394x " +
                                 withUnit(d.x, 2, "m") + "   \u0394y " + withUnit(d.y, 2, "m");
        const sf::Vector2f mid = camera.toScreen(0.5f * ((*m_tape)[0] + (*m_tape)[1]));
        const sf::Vector2f size = measureText(font, utf8(text), rowSize);
        const float pad = 5.0f * scale;
        const sf::FloatRect box(mid.x - 0.5f * size.x - pad, mid.y - size.y - 3.0f * pad, size.x + 2.0f * pad,
                                size.y + 2.0f * pad);
        drawTeachPanel(target, box, scale, "measure");
        drawLabel(target, font, utf8(text), {mid.x, box.top + pad}, rowSize, palette::kText, Align::Centre);
    }
    if (m_hover)
    {
        const PathSample& s = m_hover->sample;
        const double height = s.y - session.level().groundY;
        std::vector<PanelRow> rows{
            {"t", withUnit(s.t, 3, "s")},
            {"x", withUnit(s.x, 2, "m")},
            {"y", withUnit(s.y, 2, "m")},
            {"speed", withUnit(std::hypot(s.vx, s.vy), 2, "m/s")},
            {"height above ground", withUnit(height, 2, "m")},
        };
        const TextPanel panel(m_hover->path + (m_pinned ? " (pinned)" : ""), std::move(rows));
        const sf::Vector2f at = camera.toScreen(worldOf(s)) + sf::Vector2f(14.0f * scale, 14.0f * scale);
        const sf::Vector2f size = panel.measure(font, rowSize, rowSize, scale);
        const sf::Vector2f window(target.getSize());
        // Keep the readout on screen: flip it to the other side of the point near the edges.
        const sf::Vector2f place(at.x + size.x > window.x ? at.x - size.x - 28.0f * scale : at.x,
                                 at.y + size.y > window.y ? at.y - size.y - 28.0f * scale : at.y);
        panel.draw(target, font, place, rowSize, rowSize, scale);
    }
}

} // namespace abalike::app

#include "editor/PlayTest.hpp"

#include "editor/EditorContext.hpp"
#include "shell/AppContext.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/Sprite.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <nlohmann/json.hpp>

namespace abalike::app
{

namespace
{

/// The view in the trace: the world point at the window's top left (m) and the scale (pixels per metre).
nlohmann::json viewJson(const EditorView& view)
{
    const sf::Vector2f origin = view.toWorld({0.0f, 0.0f});
    return {origin.x, origin.y, view.pixelsPerMetre()};
}

} // namespace

void PlayTest::start()
{
    if (playing())
        return;
    m_ctx.scene().endDrag();
    m_viewBefore = m_ctx.view;
    // The first camera is the editor's view over the area the panels leave while editing.
    m_play = std::make_unique<ScenePlay>(m_ctx.app, m_ctx.scene().level(), camera());
    m_ctx.playing = true;
    m_play->aimAt(angleDeg, std::min(speedMps, m_play->maxSpeedMps()));
    m_ctx.app.trace().write("editor-play", {{"level", m_ctx.scene().level().id}, {"view", viewJson(m_ctx.view)}});
    m_ctx.say("Drag the bird back, or set the angle and speed here and Fire. Esc returns to the scene as it was.");
}

void PlayTest::stop()
{
    if (!playing())
        return;
    m_play.reset();
    m_ctx.playing = false;
    const EditorView followed = m_ctx.view;
    m_ctx.view = m_viewBefore; // the scene as it was, seen as it was
    m_ctx.app.trace().write(
        "editor-edit",
        {{"level", m_ctx.scene().level().id}, {"view", viewJson(m_ctx.view)}, {"play_view", viewJson(followed)}});
    m_ctx.say("Back to the scene as it was before the shot.");
}

Camera PlayTest::camera() const
{
    const sf::FloatRect area = m_ctx.sceneArea();
    return Camera::fromView(m_ctx.view.toWorld({area.left, area.top}), m_ctx.view.pixelsPerMetre(),
                            {static_cast<unsigned>(area.width), static_cast<unsigned>(area.height)});
}

void PlayTest::followBird()
{
    const GameSession& session = m_play->session();
    const Entity* bird = session.world().bird();
    if (bird == nullptr || bird->body == nullptr || session.phase() == Phase::Aiming)
        return;
    // Pan when the bird comes within 60 px of the play area's edge, so that it stays at least that far in.
    const Camera view = camera();
    const b2Vec2 position = bird->body->GetPosition();
    const sf::Vector2f at = view.toScreen({position.x, position.y});
    const sf::Vector2f size(view.windowSize());
    const float margin = std::min(60.0f * m_ctx.app.ui().scale(), 0.25f * std::min(size.x, size.y));
    sf::Vector2f shift(0.0f, 0.0f);
    if (at.x > size.x - margin)
        shift.x = size.x - margin - at.x;
    else if (at.x < margin)
        shift.x = margin - at.x;
    if (at.y < margin)
        shift.y = margin - at.y;
    else if (at.y > size.y - margin)
        shift.y = size.y - margin - at.y;
    if (shift.x != 0.0f || shift.y != 0.0f)
        m_ctx.view.pan(shift);
}

void PlayTest::sync()
{
    if (!playing())
        return;
    m_play->setEnvironment(m_ctx.scene().level().environment);
    if (m_ctx.scene().level().customBird)
        m_play->setCustomBird(*m_ctx.scene().level().customBird);
}

void PlayTest::handleSceneEvent(const sf::Event& event)
{
    if (playing())
        m_play->handleEvent(event);
}

void PlayTest::togglePause()
{
    if (playing())
        m_play->setFrozen(!m_play->frozen()); // paused or running, the panels stay live
}

void PlayTest::fixedUpdate()
{
    if (playing())
        m_play->fixedUpdate();
}

void PlayTest::frameUpdate(double frameS)
{
    if (!playing())
        return;
    followBird();
    m_play->setCamera(camera());
    m_play->frameUpdate(frameS);
}

void PlayTest::draw(sf::RenderTarget& target)
{
    // The play test fills the free part of the window exactly; the panels sit beside it, not over it.
    const sf::FloatRect area = m_ctx.sceneArea();
    const sf::Vector2u size(static_cast<unsigned>(area.width), static_cast<unsigned>(area.height));
    if (m_texture.getSize() != size)
        (void)m_texture.create(size.x, size.y);
    m_texture.clear();
    m_play->draw(m_texture);
    m_texture.display();
    sf::Sprite sprite(m_texture.getTexture());
    sprite.setPosition(area.left, area.top);
    target.draw(sprite);
}

} // namespace abalike::app

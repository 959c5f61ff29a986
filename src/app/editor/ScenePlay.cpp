#include "editor/ScenePlay.hpp"

#include "layers/PlayLayerTable.hpp"
#include "play/PlayDrawing.hpp"
#include "shell/AppContext.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <algorithm>

namespace abalike::app
{

ScenePlay::ScenePlay(AppContext& app, const LevelDef& level, const Camera& camera)
    : m_app(app), m_level(level), m_camera(camera), m_overlay(app.ui().font()), m_hud(app.ui().font()),
      m_layers(makePlayLayers(app))
{
    restart();
}

ScenePlay::~ScenePlay() = default;

std::string ScenePlay::levelLabel() const
{
    return session().level().id;
}

PlayMode ScenePlay::playMode() const
{
    return m_app.settings().mode();
}

void ScenePlay::restart()
{
    m_session = std::make_unique<GameSession>(m_level, Catalog::builtin());
    m_aim.reset();
    m_requestedLaunch.reset();
    m_abilityRequested = false;
    m_frozen = false;
    m_previewStale = true;
    m_app.trace().write("level", {{"id", m_level.id}, {"title", m_level.title}, {"editor", true}});
    m_trails.onLevelStart(*m_session);
    for (const auto& layer : m_layers)
        layer->onLevelStart(*this);
}

void ScenePlay::setEnvironment(const EnvironmentDef& environment)
{
    m_level.environment = environment;
    m_session->setEnvironment(environment);
    m_previewStale = true;
}

void ScenePlay::setCustomBird(const CustomBirdDef& bird)
{
    m_level.customBird = bird;
    m_session->setCustomBird(bird);
    m_previewStale = true;
}

double ScenePlay::maxSpeedMps() const
{
    return m_session->currentBird() != nullptr ? m_session->maxLaunchSpeed() : 0.0;
}

double ScenePlay::aimSpeedMps() const
{
    const auto band = m_session->band();
    return band ? band->atFraction(m_aim.powerFraction()).speedMps : 0.0;
}

void ScenePlay::aimAt(double angleDeg, double speedMps)
{
    const auto band = m_session->band();
    m_aim.set(std::clamp(angleDeg, -90.0, 90.0), band ? band->forSpeed(speedMps).fraction : 0.0);
    m_previewStale = true;
}

void ScenePlay::fire()
{
    if (m_session->phase() == Phase::Aiming && m_session->currentBird() != nullptr)
        m_requestedLaunch = ScriptedShot(m_aim.angleDeg(), aimSpeedMps());
}

void ScenePlay::handleEvent(const sf::Event& event)
{
    for (auto it = m_layers.rbegin(); it != m_layers.rend(); ++it)
        if ((*it)->handleEvent(event, *this))
            return;
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::R)
    {
        restart();
        return;
    }
    const bool click = event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left;
    const bool space = event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Space;
    if ((click || space) && m_session->canActivateAbility())
        m_abilityRequested = true;
    if (m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr || m_requestedLaunch)
        return;
    const auto pouch = m_session->launchPoint();
    const sf::Vector2f pouchPoint(static_cast<float>(pouch.x), static_cast<float>(pouch.y));
    if (m_aim.handleEvent(event, m_camera, pouchPoint))
        fire();
    m_previewStale = true;
}

void ScenePlay::fixedUpdate()
{
    if (!m_frozen && m_slowMotion.takeStep())
        physicsStep();
}

void ScenePlay::stepOnce()
{
    physicsStep();
}

void ScenePlay::physicsStep()
{
    if (m_requestedLaunch)
    {
        const ScriptedShot shot = *m_requestedLaunch;
        m_requestedLaunch.reset();
        launchRequested(m_app, *m_session, shot);
    }
    if (m_abilityRequested)
    {
        m_abilityRequested = false;
        m_session->activateAbility();
    }
    if (m_session->finished())
        return;
    m_session->step();
    if (!m_session->notice().empty())
    {
        m_app.notices().notify(m_session->notice());
        m_session->clearNotice();
    }
    m_trails.update(*m_session);
    for (const auto& layer : m_layers)
        layer->afterStep(*this);
    if (m_session->phase() == Phase::Aiming)
        m_previewStale = true;
}

void ScenePlay::refreshPreview()
{
    if (m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr)
    {
        m_preview.reset();
        return;
    }
    if (!m_previewStale && m_preview)
        return;
    m_previewStale = false;
    try
    {
        m_preview = m_session->preview(m_aim.angleDeg(), aimSpeedMps());
    }
    catch (const std::exception&)
    {
        m_preview.reset();
    }
}

void ScenePlay::frameUpdate(double frameS)
{
    refreshPreview();
    for (const auto& layer : m_layers)
        layer->frameUpdate(*this, frameS);
}

std::optional<AimReadout> ScenePlay::aim() const
{
    const auto band = m_session->band();
    if (m_session->phase() != Phase::Aiming || !band)
        return std::nullopt;
    return aimReadout(*band, m_aim.angleDeg(), band->atFraction(m_aim.powerFraction()));
}

void ScenePlay::draw(sf::RenderTarget& target)
{
    drawPlay(target, *this, m_world, m_overlay, m_hud, m_aim.pullOffset(), m_aim.dragging(), m_layers);
}

} // namespace abalike::app

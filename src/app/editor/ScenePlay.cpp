#include "editor/ScenePlay.hpp"

#include "layers/PlayLayerTable.hpp"
#include "shell/AppContext.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/Trace.hpp"

#include <algorithm>

namespace abalike::app
{

ScenePlay::ScenePlay(AppContext& app, const LevelDef& level, const Camera& camera)
    : PlayField(app, makePlayLayers(app)), m_level(level), m_camera(camera)
{
    // The scene starts live, with no settle step: bodies may still move while the first bird is aimed.
    setPreviewFollowsTheWorld(true);
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
    startLevel(std::make_unique<GameSession>(m_level, Catalog::builtin()));
    resetAim();
    m_app.trace().write("level", {{"id", m_level.id}, {"title", m_level.title}, {"editor", true}});
    levelStarted();
}

void ScenePlay::setEnvironment(const EnvironmentDef& environment)
{
    m_level.environment = environment;
    mutableSession().setEnvironment(environment);
    invalidatePreview();
}

void ScenePlay::setCustomBird(const CustomBirdDef& bird)
{
    m_level.customBird = bird;
    mutableSession().setCustomBird(bird);
    invalidatePreview();
}

double ScenePlay::maxSpeedMps() const
{
    return session().currentBird() != nullptr ? session().maxLaunchSpeed() : 0.0;
}

void ScenePlay::aimAt(double angleDeg, double speedMps)
{
    const auto band = session().band();
    m_aim.set(std::clamp(angleDeg, -90.0, 90.0), band ? band->forSpeed(speedMps).fraction : 0.0);
}

void ScenePlay::fire()
{
    if (session().phase() == Phase::Aiming && session().currentBird() != nullptr)
        requestLaunch();
}

void ScenePlay::handleEvent(const sf::Event& event)
{
    if (offerToLayers(event))
        return;
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::R)
    {
        restart();
        return;
    }
    const bool click = event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left;
    const bool space = event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Space;
    if ((click || space) && session().canActivateAbility())
        requestAbility();
    if (session().phase() != Phase::Aiming || session().currentBird() == nullptr || launchPending())
        return;
    const Vec2 pouch = session().launchPoint();
    const sf::Vector2f pouchPoint(static_cast<float>(pouch.x), static_cast<float>(pouch.y));
    if (m_aim.handleEvent(event, m_camera, pouchPoint))
        fire();
}

void ScenePlay::fixedUpdate()
{
    if (!frozen() && slowMotion().takeStep())
        physicsStep();
}

void ScenePlay::stepOnce()
{
    physicsStep();
}

void ScenePlay::physicsStep()
{
    applyRequests();
    if (session().finished())
        return;
    mutableSession().step();
    afterStep();
}

void ScenePlay::frameUpdate(double frameS)
{
    refreshPreview();
    updateLayers(frameS);
}

void ScenePlay::draw(sf::RenderTarget& target)
{
    drawField(target);
}

} // namespace abalike::app

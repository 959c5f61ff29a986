#include "play/PlayField.hpp"

#include "play/PlayDrawing.hpp"
#include "shell/AppContext.hpp"
#include "shell/Notices.hpp"
#include "shell/RunControl.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/System/Clock.hpp>
#include <exception>

namespace abalike::app
{

PlayField::PlayField(AppContext& app, std::vector<std::unique_ptr<PlayLayer>> layers)
    : m_app(app), m_hud(app.ui().font()), m_overlay(app.ui().font()), m_layers(std::move(layers))
{
}

PlayField::~PlayField() = default;

double PlayField::aimSpeedMps() const
{
    if (const std::optional<double> scripted = scriptedSpeedMps())
        return *scripted;
    const auto band = m_session->band();
    return band ? band->atFraction(m_aim.powerFraction()).speedMps : 0.0;
}

std::optional<AimReadout> PlayField::aim() const
{
    const auto band = m_session->band();
    if (m_session->phase() != Phase::Aiming || !band)
        return std::nullopt;
    // A scripted shot is given as a speed: show the pull that gives it.
    const std::optional<double> scripted = scriptedSpeedMps();
    const BandPull pull = scripted ? band->forSpeed(*scripted) : band->atFraction(m_aim.powerFraction());
    return aimReadout(*band, m_aim.angleDeg(), pull);
}

void PlayField::startLevel(std::unique_ptr<GameSession> session)
{
    m_session = std::move(session);
}

void PlayField::levelStarted()
{
    m_trails.onLevelStart(*m_session);
    for (const auto& layer : m_layers)
        layer->onLevelStart(*this);
}

void PlayField::resetAim()
{
    ++m_generation;
    m_aim.reset();
    m_requestedLaunch.reset();
    m_abilityRequested = false;
    m_frozen = false;
    m_preview.reset();
}

void PlayField::applyRequests()
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
        if (m_session->activateAbility())
            m_app.trace().write("ability", {{"t", m_session->timeSinceLaunch()}});
    }
}

void PlayField::afterStep()
{
    if (!m_session->notice().empty())
    {
        // The session reset itself (a body escaped to NaN): tell the player.
        m_app.notices().notify(m_session->notice());
        m_session->clearNotice();
    }
    m_trails.update(*m_session);
    for (const auto& layer : m_layers)
        layer->afterStep(*this);
    if (m_previewFollowsTheWorld && m_session->phase() == Phase::Aiming)
        invalidatePreview();
}

void PlayField::refreshPreview()
{
    if (m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr)
    {
        m_preview.reset();
        return;
    }
    const PreviewKey key{m_aim.angleDeg(), aimSpeedMps(), m_session->birdsUsed(), m_generation};
    if (m_preview && key == m_previewKey)
        return;
    m_previewKey = key;
    const sf::Clock clock;
    try
    {
        m_preview = m_session->preview(key.angleDeg, key.speedMps);
    }
    catch (const std::exception&)
    {
        // A preview the core cannot compute is not worth stopping the game for.
        m_preview.reset();
    }
    m_app.run().frameTimes().previewS += static_cast<double>(clock.getElapsedTime().asMicroseconds()) * 1e-6;
}

void PlayField::updateLayers(double frameS)
{
    for (const auto& layer : m_layers)
        layer->frameUpdate(*this, frameS);
}

bool PlayField::offerToLayers(const sf::Event& event)
{
    for (auto it = m_layers.rbegin(); it != m_layers.rend(); ++it)
        if ((*it)->handleEvent(event, *this))
            return true;
    return false;
}

void PlayField::drawField(sf::RenderTarget& target)
{
    drawPlay(target, *this, m_world, m_overlay, m_hud, m_aim.pullOffset(), m_aim.dragging(), m_layers);
}

} // namespace abalike::app

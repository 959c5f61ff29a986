#pragma once

#include "input/AimController.hpp"
#include "play/PlayLayer.hpp"
#include "render/Hud.hpp"
#include "render/OverlayRenderer.hpp"
#include "render/ShotTrails.hpp"
#include "render/WorldRenderer.hpp"

#include <abalike/flight/Prediction.hpp>
#include <abalike/game/GameSession.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace abalike::app
{

/// What the play screen and the editor's play test share: a session of a level, the aim at its slingshot and its
/// preview, the launch and the ability asked for until the next physics step takes them, the flown paths, the
/// drawing and the play layers. The preview is computed again only when the aim, the bird or the level changes
/// (or, where the world may still move while a bird is aimed, after every step).
class PlayField : public PlayView
{
public:
    PlayField(AppContext& app, std::vector<std::unique_ptr<PlayLayer>> layers);
    ~PlayField() override;

    // PlayView: what both play views answer alike.
    AppContext& app() override { return m_app; }
    const GameSession& session() const override { return *m_session; }
    const PredictedFlight* preview() const override { return m_preview ? &*m_preview : nullptr; }
    std::optional<AimReadout> aim() const override;
    const ShotTrails& trails() const override { return m_trails; }
    void clearTrails() override { m_trails.clear(); }
    bool frozen() const override { return m_frozen; }
    void setFrozen(bool frozen) override { m_frozen = frozen; }
    SlowMotion& slowMotion() override { return m_slowMotion; }

protected:
    /// The speed of a shot given as a speed (`--shot`) while it waits to be fired; none for an aim by hand.
    virtual std::optional<double> scriptedSpeedMps() const { return std::nullopt; }
    /// The speed the preview and a launch use: the scripted shot's, else the aim's pull on the slingshot's band.
    double aimSpeedMps() const;

    GameSession& mutableSession() { return *m_session; }
    /// Plays this session from now on (a new level, a reload); the paths and layers start the level.
    void startLevel(std::unique_ptr<GameSession> session);
    /// The paths and the layers start the level again (a new session or a restart).
    void levelStarted();
    /// Forgets the aim, the launch and ability asked for and the preview (a new level or a restart).
    void resetAim();
    /// The level changed under the aim (its air, its bird): the preview is computed again.
    void invalidatePreview() { ++m_generation; }
    /// Where the world may still move while a bird is aimed (the editor's scene starts live), the preview is
    /// computed again after every step taken while aiming.
    void setPreviewFollowsTheWorld(bool follows) { m_previewFollowsTheWorld = follows; }

    void requestLaunch() { m_requestedLaunch = ScriptedShot(m_aim.angleDeg(), aimSpeedMps()); }
    void requestAbility() { m_abilityRequested = true; }
    bool launchPending() const { return m_requestedLaunch.has_value(); }
    /// The first part of a physics step: the launch and the ability asked for go to the session.
    void applyRequests();
    /// After the session stepped: its notice to the player, the flown paths, the layers.
    void afterStep();
    /// Computes the preview for the current aim unless it is the one already computed (times it for bench frames).
    void refreshPreview();
    /// The layers' frame update.
    void updateLayers(double frameS);
    /// Offers an event to the layers, top first; true when one took it.
    bool offerToLayers(const sf::Event& event);
    void addLayer(std::unique_ptr<PlayLayer> layer) { m_layers.push_back(std::move(layer)); }
    /// Draws the session, the aim and the layers (drawPlay).
    void drawField(sf::RenderTarget& target);

    AppContext& m_app;
    std::unique_ptr<GameSession> m_session;
    AimController m_aim;
    ShotTrails m_trails;
    WorldRenderer m_world;
    Hud m_hud;

private:
    /// What the preview was computed for; a new key means the aim, the bird or the level changed.
    struct PreviewKey
    {
        double angleDeg = 0.0;
        double speedMps = 0.0;
        int birdsUsed = -1;
        int generation = -1;
        bool operator==(const PreviewKey&) const = default;
    };

    std::optional<ScriptedShot> m_requestedLaunch;
    bool m_abilityRequested = false;
    bool m_frozen = false;
    SlowMotion m_slowMotion;
    std::optional<PredictedFlight> m_preview;
    PreviewKey m_previewKey;
    int m_generation = 0;
    bool m_previewFollowsTheWorld = false;
    OverlayRenderer m_overlay;
    std::vector<std::unique_ptr<PlayLayer>> m_layers;
};

} // namespace abalike::app

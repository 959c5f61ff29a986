#pragma once

#include "input/AimController.hpp"
#include "play/PlayLayer.hpp"
#include "render/Camera.hpp"
#include "render/Hud.hpp"
#include "render/OverlayRenderer.hpp"
#include "render/ShotTrails.hpp"
#include "render/WorldRenderer.hpp"

#include <SFML/Window/Event.hpp>
#include <abalike/game/GameSession.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The editor's play mode: the scene as it is in the editor, fired at and watched with the game's own drawing
/// (preview dots, flown path, contacts, HUD) and the play layers every play screen gets (the teaching overlay).
/// It plays a copy: leaving play mode returns to the scene exactly as it was before the shot. The environment and
/// the custom bird can change while it runs.
class ScenePlay : public PlayView
{
public:
    ScenePlay(AppContext& app, const LevelDef& level, const Camera& camera);
    ~ScenePlay() override;

    /// A window event over the scene (the panels have had their chance).
    void handleEvent(const sf::Event& event);
    void fixedUpdate();
    void frameUpdate(double frameS);
    void draw(sf::RenderTarget& target);
    void setCamera(const Camera& camera) { m_camera = camera; }

    /// Starts the scene again from its definition (R).
    void restart();
    /// The air and gravity, live: the world, the bird in flight and the preview follow at once.
    void setEnvironment(const EnvironmentDef& environment);
    /// The custom bird, for the birds not yet launched.
    void setCustomBird(const CustomBirdDef& bird);
    /// Aims the bird in the slingshot (the bird panel's angle and speed) and fires if asked.
    void aimAt(double angleDeg, double speedMps);
    void fire();

    double aimSpeedMps() const;
    /// The fastest the current bird can be launched, 0 when none is waiting.
    double maxSpeedMps() const;

    // PlayView
    AppContext& app() override { return m_app; }
    PlayMode playMode() const override;
    std::string levelLabel() const override;
    const GameSession& session() const override { return *m_session; }
    const Camera& camera() const override { return m_camera; }
    const PredictedFlight* preview() const override { return m_preview ? &*m_preview : nullptr; }
    std::optional<AimReadout> aim() const override;
    const ShotTrails& trails() const override { return m_trails; }
    void clearTrails() override { m_trails.clear(); }
    bool frozen() const override { return m_frozen; }
    void setFrozen(bool frozen) override { m_frozen = frozen; }
    void stepOnce() override;
    SlowMotion& slowMotion() override { return m_slowMotion; }

private:
    void physicsStep();
    void refreshPreview();

    AppContext& m_app;
    LevelDef m_level;
    std::unique_ptr<GameSession> m_session;
    Camera m_camera;
    ShotTrails m_trails;
    AimController m_aim;
    std::optional<ScriptedShot> m_requestedLaunch;
    bool m_abilityRequested = false;
    bool m_frozen = false;
    SlowMotion m_slowMotion;
    std::optional<PredictedFlight> m_preview;
    bool m_previewStale = true;
    WorldRenderer m_world;
    OverlayRenderer m_overlay;
    Hud m_hud;
    std::vector<std::unique_ptr<PlayLayer>> m_layers;
};

} // namespace abalike::app

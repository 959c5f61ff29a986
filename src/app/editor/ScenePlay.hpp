#pragma once

#include "play/PlayField.hpp"
#include "render/Camera.hpp"

#include <SFML/Window/Event.hpp>
#include <abalike/game/GameSession.hpp>

namespace abalike::app
{

class AppContext;

/// The editor's play mode: the scene as it is in the editor, fired at and watched with the game's own drawing
/// (preview dots, flown path, contacts, HUD) and the play layers every play screen gets (the teaching overlay).
/// It plays a copy: leaving play mode returns to the scene exactly as it was before the shot. The environment and
/// the custom bird can change while it runs. Aiming, the preview and the steps are the play screen's (PlayField).
class ScenePlay : public PlayField
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

    double aimSpeedMps() const { return PlayField::aimSpeedMps(); }
    /// The fastest the current bird can be launched, 0 when none is waiting.
    double maxSpeedMps() const;

    // PlayView
    PlayMode playMode() const override;
    std::string levelLabel() const override;
    const Camera& camera() const override { return m_camera; }
    void stepOnce() override;

private:
    void physicsStep();

    LevelDef m_level;
    Camera m_camera;
};

} // namespace abalike::app

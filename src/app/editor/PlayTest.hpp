#pragma once

#include "editor/EditorView.hpp"
#include "editor/ScenePlay.hpp"

#include <SFML/Graphics/RenderTexture.hpp>
#include <memory>

namespace abalike::app
{

struct EditorContext;

/// The editor's play test (F5): the scene as it is, fired at in the free part of the window, and back to the scene
/// as it was. Keeps the launch set in the panels (angle and speed, or the band's pull) between tests.
class PlayTest
{
public:
    explicit PlayTest(EditorContext& context) : m_ctx(context) {}

    bool playing() const { return m_play != nullptr; }
    void start();
    void stop();
    /// The environment and the custom bird are live while the scene plays.
    void sync();
    /// A key or mouse event for the play (mouse coordinates in the play area's pixels).
    void handleSceneEvent(const sf::Event& event);
    void togglePause();
    void fixedUpdate();
    void frameUpdate(double frameS);
    /// Draws the play into the free part of the window (the panels sit beside it, not over it).
    void draw(sf::RenderTarget& target);

    /// The play under way; only while playing().
    ScenePlay& play() { return *m_play; }
    const ScenePlay& play() const { return *m_play; }

    double angleDeg = 45.0;
    double speedMps = 15.0;
    bool aimByPull = false; ///< the launch is set by the band's pull, not the bird's speed
    double altitudeM = 0.0;

private:
    /// The play test's camera: the editor's view, over the part of the window the panels leave free.
    Camera camera() const;
    /// Keeps the bird in flight inside the play area by panning the view after it.
    void followBird();

    EditorContext& m_ctx;
    std::unique_ptr<ScenePlay> m_play;
    EditorView m_viewBefore;     ///< the view when the play started: it follows the bird, and comes back with the scene
    sf::RenderTexture m_texture; ///< the play is drawn here, then into the free part of the window
};

} // namespace abalike::app

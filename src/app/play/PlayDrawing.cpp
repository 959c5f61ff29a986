#include "play/PlayDrawing.hpp"

#include "render/ScreenRegions.hpp"

#include "input/AimController.hpp"
#include "play/PlayToolbar.hpp"
#include "render/LabelPlacement.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/PullReach.hpp"
#include "render/TrailPainter.hpp"
#include "shell/AppContext.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/View.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app
{

namespace
{
constexpr float kLastShotFade = 0.45f;

/// The circle the pointer pulls within (its edge is a full pull, the same size on the screen at every zoom), dashed
/// around the pouch.
void drawPullLimit(sf::RenderTarget& target, const Camera& camera, const GameSession& session, bool pulling,
                   float uiScale)
{
    const auto launch = session.launchPoint();
    const sf::Vector2f pouch = camera.toScreen({static_cast<float>(launch.x), static_cast<float>(launch.y)});
    const float radius = fullPullPx(camera.windowSize());
    const sf::Color colour = faded(palette::kPreviewDot, pulling ? 0.85f : 0.3f);
    const float width = (pulling ? 2.5f : 1.5f) * uiScale;
    constexpr int kDashes = 36;
    Mesh mesh;
    for (int i = 0; i < kDashes; ++i)
    {
        // Each dash covers half of its share of the circle.
        const float a0 = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kDashes;
        const float a1 = a0 + std::numbers::pi_v<float> / kDashes;
        mesh.addLine(pouch + radius * sf::Vector2f(std::cos(a0), std::sin(a0)),
                     pouch + radius * sf::Vector2f(std::cos(a1), std::sin(a1)), width, colour);
    }
    mesh.draw(target);
}

/// The level as the player sees it: sky, terrain, bodies, slingshot, the shots' paths and the preview.
void drawWorldPicture(sf::RenderTarget& target, PlayView& view, WorldRenderer& world, OverlayRenderer& overlay,
                      sf::Vector2f pullOffset, bool pulling, const ShotRecord* lastShot, float opacity,
                      bool previewHidden)
{
    const GameSession& session = view.session();
    const Camera& camera = view.camera();
    world.drawBackground(target, camera, session);

    // Earlier shots on this level stay as dimmed trails (unless the player turned flown paths off).
    if (view.app().settings().current().showActualPath)
        drawShotTrails(target, camera, view.trails(), view.app().ui().scale());
    if (lastShot != nullptr)
        overlay.drawShotPaths(target, camera, *lastShot, opacity);
    world.drawForeground(target, camera, session, pullOffset);
    if (view.aim())
        drawPullLimit(target, camera, session, pulling, view.app().ui().scale());
    if (lastShot != nullptr)
        overlay.drawShotMarkers(target, camera, *lastShot, opacity);
    // The preview setting: the whole path, its climb to the top of the arc (at least half a second), or none.
    const PreviewMode previewMode = view.app().settings().current().previewFor(view.playMode());
    if (const PredictedFlight* preview = view.preview();
        preview != nullptr && previewMode != PreviewMode::Off && !previewHidden)
        overlay.drawPreview(target, camera, *preview,
                            previewMode == PreviewMode::Short ? shortPreviewDots(*preview) : 0);
}
} // namespace

void drawPlay(sf::RenderTarget& target, PlayView& view, WorldRenderer& world, OverlayRenderer& overlay, const Hud& hud,
              sf::Vector2f pullOffset, bool pulling, const std::vector<std::unique_ptr<PlayLayer>>& layers)
{
    // One layout per frame: every panel drawn from here on is recorded, and later panels keep clear of earlier ones.
    beginScreenLayout();
    const GameSession& session = view.session();
    const Camera& camera = view.camera();
    // A shake moves the world's picture, never the HUD and panels over it.
    sf::Vector2f shakePx(0.0f, 0.0f);
    for (const auto& layer : layers)
        shakePx += layer->worldShakePx(view);
    const sf::View still = target.getView();
    if (shakePx != sf::Vector2f(0.0f, 0.0f))
    {
        // Moved, the picture would leave a strip of bare window at one edge: it also zooms in by as much, so the
        // shaken view stays inside what the still one shows.
        sf::View shaken = still;
        shaken.move(-shakePx);
        const sf::Vector2f size = still.getSize();
        const float margin = std::max(std::abs(shakePx.x) / size.x, std::abs(shakePx.y) / size.y);
        shaken.zoom(std::max(0.5f, 1.0f - 2.0f * margin));
        target.setView(shaken);
    }
    // While the next bird is aimed, the last shot stays as a faded reference.
    const ShotRecord* lastShot = session.shots().empty() ? nullptr : &session.shots().back();
    const float opacity = session.phase() == Phase::Aiming ? kLastShotFade : 1.0f;
    // A frame only laid out (the layout tests) leaves the world's picture out: no panel's place depends on it.
    if (drawingPixels())
    {
        const bool previewHidden =
            std::any_of(layers.begin(), layers.end(), [&view](const auto& layer) { return layer->hidesPreview(view); });
        drawWorldPicture(target, view, world, overlay, pullOffset, pulling, lastShot, opacity, previewHidden);
        for (const auto& layer : layers)
            layer->drawWorld(target, view);
    }

    target.setView(still);
    // What the panels must leave in view; the HUD's strips give way to all but the slingshot (the camera keeps the
    // ground and the slingshot above the bottom strips).
    std::vector<ScreenRegion> things = keepVisibleBoxes(session, camera);
    std::vector<sf::FloatRect> stripsKeepClear;
    for (const ScreenRegion& thing : things)
        if (thing.name != "slingshot")
            stripsKeepClear.push_back(thing.rect);
    hud.draw(target, target.getSize(), session, view.aim(), view.playMode(), view.levelLabel(),
             static_cast<float>(view.app().settings().current().textScale),
             PlayToolbar::reservedWidthPx(view.app(), target.getSize()), stripsKeepClear);
    for (const auto& layer : layers)
        layer->drawScreen(target, view);
    // Last, so that it can keep clear of every panel.
    std::vector<ScreenRegion>* sink = keepVisibleSink();
    if (lastShot != nullptr)
        overlay.drawShotLabel(target, camera, *lastShot, opacity, structureScreenBoxes(session, camera),
                              rectsOf(things), static_cast<float>(view.app().settings().current().textScale),
                              view.playMode() == PlayMode::Game);
    if (sink != nullptr)
        *sink = std::move(things);
}

bool launchRequested(AppContext& app, GameSession& session, const ScriptedShot& shot)
{
    try
    {
        session.launch(shot.angleDeg, shot.speedMps);
        app.trace().write("launch", {{"angle_deg", shot.angleDeg}, {"speed", shot.speedMps}});
        return true;
    }
    catch (const LaunchError& error)
    {
        app.notices().notify(error.what());
        return false;
    }
}

} // namespace abalike::app

#include "render/CameraRig.hpp"

#include "render/PullReach.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr float kBirdMarginM = 1.5f;      ///< room kept around each bird
constexpr float kBirdMarginPx = 24.0f;    ///< ... and never less than this on screen
constexpr float kLeadS = 0.6f;            ///< the camera looks this far ahead of the bird
constexpr float kStructureMarginM = 1.5f; ///< room around the structure
constexpr float kManualZoomOut = 4.0f;    ///< the player may zoom out to this many times the home view
/// The ground line goes up at most this far to make room for a full pull (a short wide window): beyond it the
/// view slides instead.
constexpr float kMostGroundUp = 0.45f;

/// Panels that leave the level less than this share of the window's height (the teaching overlay at large text) keep
/// the ground where they put it: raising it for a steep full pull would push the pigs under the panels.
constexpr float kLeastLevelShareForRoomBelow = 0.45f;

bool keepsRoomBelow(const CameraFocus& focus)
{
    return 1.0f - focus.topReserved - focus.groundFromBottom >= kLeastLevelShareForRoomBelow;
}

float easing(double frameS, double timeS)
{
    return static_cast<float>(1.0 - std::exp(-std::max(frameS, 0.0) / timeS));
}
} // namespace

void CameraRig::reset(const CameraFocus& focus, sf::Vector2u windowSize)
{
    m_window = windowSize;
    m_home = focus.home;
    m_groundY = focus.groundY;
    m_mode = focus.shotUnderWay ? Mode::Follow : Mode::Home;
    m_shotUnderWay = focus.shotUnderWay;
    m_view = target(focus);
    m_snap = false;
    rebuild();
}

void CameraRig::resize(sf::Vector2u windowSize)
{
    // Keep what was in view in view: the same centre, scaled by the smaller change so nothing is cut off.
    const float sx = static_cast<float>(std::max(windowSize.x, 1u)) / static_cast<float>(std::max(m_window.x, 1u));
    const float sy = static_cast<float>(std::max(windowSize.y, 1u)) / static_cast<float>(std::max(m_window.y, 1u));
    m_view.pixelsPerMetre = std::clamp(m_view.pixelsPerMetre * std::min(sx, sy), camera_limits::kMinPixelsPerMetre,
                                       camera_limits::kMaxPixelsPerMetre);
    m_window = windowSize;
    m_snap = m_mode == Mode::Home;
    rebuild();
}

bool CameraRig::homeShowsEveryActionPig(const CameraFocus& focus) const
{
    const WorldBox home = visibleBox(homeView(focus), m_window);
    return std::all_of(focus.actionPigs.begin(), focus.actionPigs.end(),
                       [&home](const WorldBox& pig) { return home.contains(pig); });
}

bool CameraRig::homeShowsTheSettling(const CameraFocus& focus) const
{
    // A pig the last of the action may still reach stays in view: a home view that leaves it out waits for the world.
    return focus.settling && homeShowsEveryActionPig(focus);
}

CameraView CameraRig::target(const CameraFocus& focus) const
{
    if (m_mode == Mode::Manual)
        return m_view;
    if (m_mode == Mode::Home || m_mode == Mode::Opening)
        return homeView(focus);
    if (focus.afterImpact)
    {
        // Frame the action; when nothing moves any more, the level as designed.
        if (focus.action.empty())
            return homeView(focus);
        WorldBox action = focus.action.front();
        for (const WorldBox& box : focus.action)
            action = action.united(box);
        return fitBox(action.expanded(kStructureMarginM), focus.groundY, m_window, focus.topReserved,
                      focus.groundFromBottom);
    }
    if (focus.birds.empty() && !focus.structure)
        return homeView(focus);

    std::optional<WorldBox> box = focus.structure;
    if (box)
        *box = box->expanded(kStructureMarginM);
    for (std::size_t i = 0; i < focus.birds.size(); ++i)
    {
        WorldBox bird = focus.birds[i].expanded(kBirdMarginM);
        if (i == 0)
        {
            // Lead the launched bird a little so it flies into the picture, not out of it.
            const sf::Vector2f ahead = focus.birds[0].centre() + focus.birdVelocityMps * kLeadS;
            bird = bird.united(WorldBox::around(ahead, kBirdMarginM));
        }
        box = box ? box->united(bird) : bird;
    }
    CameraView view = fitBox(*box, focus.groundY, m_window, focus.topReserved, focus.groundFromBottom);
    if (focus.birdDiameterM > 0.0f && view.pixelsPerMetre * focus.birdDiameterM < kMinBirdPx && !focus.birds.empty())
    {
        // The structure is too far to keep in view with the bird drawn at a visible size: follow the bird.
        WorldBox lead = focus.birds[0].expanded(kBirdMarginM);
        lead = lead.united(WorldBox::around(focus.birds[0].centre() + focus.birdVelocityMps * kLeadS, kBirdMarginM));
        view = fitBox(lead, focus.groundY, m_window, focus.topReserved, focus.groundFromBottom);
        view.pixelsPerMetre = std::max(view.pixelsPerMetre, kMinBirdPx / focus.birdDiameterM);
    }
    return view;
}

void CameraRig::update(const CameraFocus& focus, double frameS)
{
    m_home = focus.home;
    m_groundY = focus.groundY;
    if (focus.shotUnderWay && !m_shotUnderWay)
        m_mode = Mode::Follow; // launch: follow, whatever the player had panned to (or the opening pan showed)
    else if ((focus.shotUnderWay && m_mode == Mode::Follow && (focus.birdDue || homeShowsTheSettling(focus))) ||
             (!focus.shotUnderWay && m_shotUnderWay && m_mode != Mode::Home))
    {
        m_mode = Mode::Home; // the shot is settling or the world settled: back to the level, in kReturnS
        m_settledEarly = focus.shotUnderWay;
        startReturn();
    }
    else if (focus.shotUnderWay && m_mode == Mode::Home && m_settledEarly && !focus.birdDue &&
             !homeShowsEveryActionPig(focus))
    {
        m_mode = Mode::Follow; // it moved again near a pig the home view leaves out: follow the action once more
        m_settledEarly = false;
    }
    m_shotUnderWay = focus.shotUnderWay;

    if (m_mode == Mode::Opening)
    {
        // From the far end to the slingshot, easing in and out; a launch takes over at once (above).
        m_openingS += std::max(frameS, 0.0);
        const auto t = static_cast<float>(std::min(m_openingS / kOpeningS, 1.0));
        const float s = t * t * (3.0f - 2.0f * t);
        const CameraView home = homeView(focus);
        m_view.centreM = m_openingFrom.centreM + (home.centreM - m_openingFrom.centreM) * s;
        m_view.pixelsPerMetre = home.pixelsPerMetre;
        if (t >= 1.0f)
            m_mode = Mode::Home;
        rebuild();
        return;
    }
    CameraView goal = target(focus);
    // In flight the camera never comes closer than the aiming view (a short shot filled the window with the
    // slingshot), unless the aiming view draws the bird smaller than kMinBirdPx.
    if (m_mode == Mode::Follow)
        goal.pixelsPerMetre = std::min(goal.pixelsPerMetre,
                                       std::max(homeView(focus).pixelsPerMetre,
                                                focus.birdDiameterM > 0.0f ? kMinBirdPx / focus.birdDiameterM : 0.0f));
    const auto moved = [](const CameraView& a, const CameraView& b)
    {
        return a.centreM != b.centreM || a.pixelsPerMetre != b.pixelsPerMetre;
    };
    if (m_mode == Mode::Home && !m_snap && moved(goal, m_returnGoal))
        startReturn();
    m_returnGoal = goal;
    if (m_snap)
        m_view = goal;
    else if (m_mode == Mode::Home && m_returnS < kReturnS)
    {
        m_returnS = std::min(kReturnS, m_returnS + std::max(frameS, 0.0));
        const auto t = static_cast<float>(m_returnS / kReturnS);
        const float s = t * t * (3.0f - 2.0f * t);
        m_view.centreM = m_returnFrom.centreM + (goal.centreM - m_returnFrom.centreM) * s;
        m_view.pixelsPerMetre = std::exp(std::log(m_returnFrom.pixelsPerMetre) +
                                         (std::log(goal.pixelsPerMetre) - std::log(m_returnFrom.pixelsPerMetre)) * s);
    }
    else if (m_mode == Mode::Home)
        m_view = goal; // home, and at rest
    else if (m_mode != Mode::Manual)
    {
        const float k = easing(frameS, kFollowTimeS);
        m_view.centreM += (goal.centreM - m_view.centreM) * k;
        // Zoom eases in log space, so zooming in and out feel alike.
        const float logPpm = std::log(m_view.pixelsPerMetre);
        m_view.pixelsPerMetre = std::exp(logPpm + (std::log(goal.pixelsPerMetre) - logPpm) * k);
    }
    m_snap = false;
    // Easing out of a wide view must not draw the launched bird as a speck on the way.
    if (m_mode == Mode::Follow && !focus.afterImpact && focus.birdDiameterM > 0.0f)
        m_view.pixelsPerMetre = std::max(m_view.pixelsPerMetre, kMinBirdPx / focus.birdDiameterM);
    if (m_mode != Mode::Home)
        keepInView(focus);
    rebuild();
}

void CameraRig::keepInView(const CameraFocus& focus)
{
    // In flight the birds must be on screen; after the impact, the pigs the action may reach.
    const std::vector<WorldBox>& must = focus.afterImpact ? focus.actionPigs : focus.birds;
    if (must.empty())
        return;
    const float margin = std::max(0.5f, kBirdMarginPx / m_view.pixelsPerMetre);
    WorldBox needed = must.front().expanded(margin);
    for (const WorldBox& box : must)
        needed = needed.united(box.expanded(margin));
    const WorldBox visible = visibleBox(m_view, m_window);
    if (visible.contains(needed))
        return;
    if (m_mode == Mode::Manual)
    {
        // The player looks elsewhere on purpose; birds off screen get edge markers instead.
        return;
    }
    if (needed.width() <= visible.width() && needed.height() <= visible.height())
    {
        // Slide the least distance that brings every bird in.
        sf::Vector2f shift;
        if (needed.left < visible.left)
            shift.x = needed.left - visible.left;
        else if (needed.right > visible.right)
            shift.x = needed.right - visible.right;
        if (needed.bottom < visible.bottom)
            shift.y = needed.bottom - visible.bottom;
        else if (needed.top > visible.top)
            shift.y = needed.top - visible.top;
        m_view.centreM += shift;
        return;
    }
    const WorldBox both = visible.united(needed);
    const sf::Vector2f window(static_cast<float>(std::max(m_window.x, 1u)),
                              static_cast<float>(std::max(m_window.y, 1u)));
    m_view.pixelsPerMetre = std::clamp(std::min(window.x / both.width(), window.y / both.height()),
                                       camera_limits::kMinPixelsPerMetre, camera_limits::kMaxPixelsPerMetre);
    m_view.centreM = both.centre();
}

void CameraRig::panPixels(sf::Vector2f deltaPx)
{
    m_mode = Mode::Manual;
    // Screen y points down, world y up.
    m_view.centreM += sf::Vector2f(-deltaPx.x, deltaPx.y) / m_view.pixelsPerMetre;
    clampManual();
    rebuild();
}

void CameraRig::zoomAt(float factor, sf::Vector2f pixel)
{
    m_mode = Mode::Manual;
    const sf::Vector2f before = m_camera.toWorld(pixel);
    m_view.pixelsPerMetre *= factor;
    clampManual();
    // Keep the world point under the pointer where it was.
    const Camera zoomed = Camera::centredOn(m_view.centreM, m_view.pixelsPerMetre, m_window);
    m_view.centreM += before - zoomed.toWorld(pixel);
    clampManual();
    rebuild();
}

void CameraRig::clampManual()
{
    const CameraView home = fitBox(m_home, m_groundY, m_window);
    const float minPpm = std::max(camera_limits::kMinPixelsPerMetre, home.pixelsPerMetre / kManualZoomOut);
    m_view.pixelsPerMetre = std::clamp(m_view.pixelsPerMetre, minPpm, camera_limits::kMaxPixelsPerMetre);
    // The middle of the window stays over the level or next to it, so the player cannot get lost in empty sky.
    const WorldBox allowed = m_home.expanded(0.5f * std::max(m_home.width(), m_home.height()));
    m_view.centreM.x = std::clamp(m_view.centreM.x, allowed.left, allowed.right);
    m_view.centreM.y = std::clamp(m_view.centreM.y, m_groundY, allowed.top);
}

void CameraRig::recentre()
{
    m_mode = m_shotUnderWay ? Mode::Follow : Mode::Home;
    startReturn();
}

void CameraRig::holdStill()
{
    if (m_mode == Mode::Home && m_returnS < kReturnS)
        m_mode = Mode::Manual;
}

void CameraRig::startReturn()
{
    m_returnFrom = m_view;
    m_returnS = 0.0;
}

CameraRig::HomeFit CameraRig::fitHome(const CameraFocus& focus, const WorldBox& box, float groundFromBottom) const
{
    const CameraView whole = fitBox(box, focus.groundY, m_window, focus.topReserved, groundFromBottom);
    if (focus.smallestPigM <= 0.0f || whole.pixelsPerMetre * focus.smallestPigM >= kMinPigPx)
        return {whole, false};
    // The scale that draws the smallest pig kMinPigPx tall, the slingshot's end of the level at the left edge, the
    // ground where fitBox keeps it.
    const float ppm = std::min(kMinPigPx / focus.smallestPigM, camera_limits::kMaxPixelsPerMetre);
    const sf::Vector2f window(static_cast<float>(std::max(m_window.x, 1u)),
                              static_cast<float>(std::max(m_window.y, 1u)));
    const float visibleWidth = window.x / ppm;
    const float visibleHeight = window.y / ppm;
    const float base = std::min(box.bottom, focus.groundY);
    return {{{box.left + 0.5f * visibleWidth, base + (0.5f - groundFromBottom) * visibleHeight}, ppm}, true};
}

CameraRig::HomeFit CameraRig::homeFit(const CameraFocus& focus) const
{
    HomeFit fit = fitHome(focus, focus.home, focus.groundFromBottom);
    if (!focus.pouchM)
        return fit;
    // Room for a full pull: the box reaches further left of the pouch and the ground line goes up until the pouch has
    // the room at the scale that results. Each pass lowers the scale a little less; a few are plenty.
    const PullRoom room = pullRoomPx(m_window);
    const auto windowHeight = static_cast<float>(std::max(m_window.y, 1u));
    const sf::Vector2f pouch = *focus.pouchM;
    WorldBox box = focus.home;
    float ground = focus.groundFromBottom;
    constexpr int kPasses = 6;
    for (int pass = 0; pass < kPasses; ++pass)
    {
        const float ppm = fit.view.pixelsPerMetre;
        box.left = std::min(focus.home.left, pouch.x - room.left / ppm);
        const float pouchAboveGroundPx = (pouch.y - std::min(focus.home.bottom, focus.groundY)) * ppm;
        if (keepsRoomBelow(focus))
            ground =
                std::clamp((room.below - pouchAboveGroundPx) / windowHeight, focus.groundFromBottom, kMostGroundUp);
        fit = fitHome(focus, box, ground);
    }
    // What the last pass's scale still lacks (a fraction of a pixel, or beyond the most the ground may go up): slide.
    CameraView& view = fit.view;
    const Camera camera = Camera::centredOn(view.centreM, view.pixelsPerMetre, m_window);
    const sf::Vector2f pouchPx = camera.toScreen(pouch);
    view.centreM.x -= std::max(room.left - pouchPx.x, 0.0f) / view.pixelsPerMetre;
    // A slingshot on a high hill may sit so near the top that a flat pull would leave it: the view goes up.
    const float belowLacksPx = keepsRoomBelow(focus) ? std::max(room.below - (windowHeight - pouchPx.y), 0.0f) : 0.0f;
    const float pouchDownPx = std::max(room.above - pouchPx.y, 0.0f) - belowLacksPx;
    view.centreM.y += pouchDownPx / view.pixelsPerMetre;
    return fit;
}

CameraView CameraRig::homeView(const CameraFocus& focus) const
{
    return homeFit(focus).view;
}

bool CameraRig::homeLeavesLevelOut(const CameraFocus& focus) const
{
    return homeFit(focus).leavesLevelOut;
}

bool CameraRig::startOpening(const CameraFocus& focus)
{
    if (focus.shotUnderWay || !homeLeavesLevelOut(focus))
        return false;
    const CameraView home = homeView(focus);
    const float halfWidth = 0.5f * static_cast<float>(std::max(m_window.x, 1u)) / home.pixelsPerMetre;
    m_openingFrom = {{std::max(home.centreM.x, focus.home.right - halfWidth), home.centreM.y}, home.pixelsPerMetre};
    m_openingS = 0.0;
    m_mode = Mode::Opening;
    m_view = m_openingFrom;
    rebuild();
    return true;
}

void CameraRig::skipOpening()
{
    if (m_mode != Mode::Opening)
        return;
    m_mode = Mode::Home;
    m_snap = true;
}

void CameraRig::rebuild()
{
    m_camera = Camera::centredOn(m_view.centreM, m_view.pixelsPerMetre, m_window);
}

} // namespace abalike::app

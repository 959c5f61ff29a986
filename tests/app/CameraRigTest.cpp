// The play screen's camera, headless: fitting every campaign level in windows of every shape, following every
// campaign level's reference shot with the bird always in view, returning when the world settles, and the
// player's pan and zoom.
#include "render/CameraRig.hpp"
#include "render/CameraControls.hpp"
#include "render/CameraFocus.hpp"
#include "render/LabelPlacement.hpp"
#include "render/PullReach.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

namespace
{
const Campaign& campaign()
{
    static const Campaign loaded =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    return loaded;
}

const std::vector<sf::Vector2u>& windowShapes()
{
    static const std::vector<sf::Vector2u> shapes{{1280, 720}, {800, 600}, {1920, 1080}, {600, 1000}};
    return shapes;
}

bool inside(const sf::FloatRect& visible, sf::Vector2f point, float marginM = 0.0f)
{
    return point.x >= visible.left + marginM && point.x <= visible.left + visible.width - marginM &&
           point.y >= visible.top + marginM && point.y <= visible.top + visible.height - marginM;
}

/// 1-1, a small level that fits any window at once.
const LevelDef& firstFlight()
{
    return campaign().levels.at(campaign().indexOf("1-1").value()).level;
}

sf::Vector2f positionOf(const Entity& entity)
{
    const b2Vec2 p = entity.body->GetPosition();
    return {p.x, p.y};
}
} // namespace

TEST(CameraFit, EveryCampaignLevelStartsWithTheSlingshotAndEveryBodyInViewInEveryWindowShape)
{
    ASSERT_EQ(campaign().levels.size(), 50u);
    for (const CampaignLevel& entry : campaign().levels)
        for (const sf::Vector2u window : windowShapes())
        {
            SCOPED_TRACE(entry.level.id + " in " + std::to_string(window.x) + "x" + std::to_string(window.y));
            GameSession session(entry.level);
            CameraRig rig;
            rig.reset(cameraFocusOf(session), window);
            const sf::FloatRect visible = rig.camera().visibleWorld();
            // One scale for both axes: the window's shape is the visible world's shape (no stretching).
            EXPECT_NEAR(visible.width / visible.height, static_cast<float>(window.x) / static_cast<float>(window.y),
                        1e-3f);
            const auto launch = session.launchPoint();
            EXPECT_TRUE(inside(visible, {static_cast<float>(launch.x), static_cast<float>(launch.y)}, 1.0f));
            // The smallest pig is drawn at least kMinPigPx tall while aiming.
            const CameraFocus focus = cameraFocusOf(session);
            EXPECT_GE(rig.view().pixelsPerMetre * focus.smallestPigM, kMinPigPx - 1e-3f);
            // Every body is in view, or (a level wider than that) the opening pan sweeps from a view that shows
            // the level's far end to this one, so every body is shown on the way.
            sf::FloatRect swept = visible;
            if (rig.homeLeavesLevelOut(focus))
            {
                CameraRig opening;
                opening.reset(focus, window);
                ASSERT_TRUE(opening.startOpening(focus));
                const sf::FloatRect first = opening.camera().visibleWorld();
                EXPECT_NEAR(first.top, visible.top, 1e-3f);
                swept.width = first.left + first.width - visible.left;
            }
            for (const Entity& entity : session.world().entities())
            {
                if (entity.body != nullptr && (entity.kind == EntityKind::Block || entity.kind == EntityKind::Pig))
                {
                    EXPECT_TRUE(inside(swept, positionOf(entity))) << entity.typeName << " at " << positionOf(entity).x;
                }
            }
        }
}

TEST(CameraFit, AWideLevelOpensWithAPanFromItsFarEndToTheSlingshotThatAnyInputOrALaunchEnds)
{
    // A small pig 120 m out: the whole level would draw it 6 px tall in 1280 x 720.
    LevelDef level;
    level.id = "wide";
    level.title = "Wide";
    level.birds = {"red"};
    level.pigs.push_back({"small", 120.0, 0.25});
    const sf::Vector2u window{1280, 720};
    GameSession session(level);
    const CameraFocus focus = cameraFocusOf(session);
    CameraRig rig;
    rig.reset(focus, window);
    ASSERT_TRUE(rig.homeLeavesLevelOut(focus));
    const CameraView home = rig.homeView(focus);
    EXPECT_NEAR(home.pixelsPerMetre * 0.5f, kMinPigPx, 1e-3f); // the pig just 12 px tall
    ASSERT_TRUE(rig.startOpening(focus));
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Opening);
    EXPECT_TRUE(inside(rig.camera().visibleWorld(), {120.0f, 0.25f})); // it starts at the pig
    const float startX = rig.view().centreM.x;
    rig.update(focus, 1.25); // half way in time, half way in distance (the easing is symmetric)
    EXPECT_NEAR(rig.view().centreM.x, 0.5f * (startX + home.centreM.x), 0.01f);
    for (int i = 0; i < 80; ++i)
        rig.update(focus, 1.0 / 60.0);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);
    EXPECT_NEAR(rig.view().centreM.x, home.centreM.x, 1e-3f);
    EXPECT_TRUE(inside(rig.camera().visibleWorld(), {0.0f, 1.5f}, 1.0f)); // the slingshot

    // Any input: home at the next frame.
    ASSERT_TRUE(rig.startOpening(focus));
    rig.update(focus, 0.1);
    rig.skipOpening();
    rig.update(focus, 1.0 / 60.0);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);
    EXPECT_NEAR(rig.view().centreM.x, home.centreM.x, 1e-3f);

    // A launch: the camera follows the bird at once.
    ASSERT_TRUE(rig.startOpening(focus));
    session.launch(30.0, 20.0);
    session.step();
    rig.update(cameraFocusOf(session), 1.0 / 60.0);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Follow);

    // A level that fits has no opening pan.
    GameSession small(firstFlight());
    CameraRig fits;
    fits.reset(cameraFocusOf(small), window);
    EXPECT_FALSE(fits.startOpening(cameraFocusOf(small)));
}

/// The live pigs within kActionReachM of a moving block or pig: after an impact they must be in the window.
std::vector<sf::Vector2f> pigsNearTheAction(const GameSession& session)
{
    std::vector<sf::Vector2f> moving;
    for (const Entity& e : session.world().entities())
        if (e.alive && e.body != nullptr && (e.kind == EntityKind::Block || e.kind == EntityKind::Pig))
        {
            const b2Vec2 v = e.body->GetLinearVelocity();
            if (std::hypot(v.x, v.y) > 0.3f || std::abs(e.body->GetAngularVelocity()) > 0.5f)
                moving.push_back(positionOf(e));
        }
    std::vector<sf::Vector2f> pigs;
    for (const Entity& e : session.world().entities())
        if (e.alive && e.body != nullptr && e.kind == EntityKind::Pig)
            for (const sf::Vector2f m : moving)
                if (std::hypot(m.x - positionOf(e).x, m.y - positionOf(e).y) <= kActionReachM)
                {
                    pigs.push_back(positionOf(e));
                    break;
                }
    return pigs;
}

/// Flies one shot with the rig: until the first contact the bird is in view (at least kMinBirdPx wide or the
/// structure in view too), then until the next bird is ready every pig the action may reach is. Returns the steps
/// that broke it.
struct Watched
{
    int steps = 0;
    int birdOut = 0;
    int pigOut = 0;
    int birdTooSmall = 0;
    /// Steps drawn closer than the aiming view: before the first contact unless the aiming view draws the bird under
    /// kMinBirdPx; after it, steps that zoom in past the aiming view (easing out of the bird's zoom is allowed).
    int closerThanHome = 0;
    int impactSteps = 0;
};

Watched watchShot(GameSession& session, CameraRig& rig, sf::Vector2u window, double angleDeg, double speedMps,
                  const CameraView& home, int* outsideHomeView)
{
    Watched w;
    float lastPpm = rig.view().pixelsPerMetre;
    session.launch(angleDeg, speedMps);
    while (session.phase() == Phase::Flying && w.steps < 60 * 120)
    {
        session.step();
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
        ++w.steps;
        const ShotRecord& shot = session.shots().back();
        const Entity* flying = session.world().bird();
        const float ppm = rig.view().pixelsPerMetre;
        if (shot.actualContact || shot.contactTimeS)
            w.closerThanHome += ppm > home.pixelsPerMetre * 1.0001f && ppm > lastPpm * 1.0001f ? 1 : 0;
        else if (flying != nullptr &&
                 ppm > std::max(home.pixelsPerMetre, kMinBirdPx / static_cast<float>(flying->widthM)) * 1.0001f)
            ++w.closerThanHome;
        lastPpm = ppm;
        const sf::FloatRect visible = rig.camera().visibleWorld();
        if (shot.actualContact || shot.contactTimeS)
        {
            ++w.impactSteps;
            // The last kReturnHomeS before the next bird is due (and once it is ready) the camera heads home, whatever
            // still moves.
            if (session.phase() != Phase::Flying || cameraFocusOf(session).birdDue)
                continue;
            for (const sf::Vector2f pig : pigsNearTheAction(session))
                if (!inside(visible, pig))
                    ++w.pigOut;
            continue;
        }
        const Entity* bird = session.world().bird();
        if (bird == nullptr || bird->body == nullptr || !bird->alive)
            continue;
        if (!inside(visible, positionOf(*bird)))
            ++w.birdOut;
        if (rig.view().pixelsPerMetre * static_cast<float>(bird->widthM) < kMinBirdPx - 0.01f)
            ++w.birdTooSmall;
        if (outsideHomeView != nullptr && !visibleBox(home, window).contains(positionOf(*bird)))
            ++*outsideHomeView;
    }
    return w;
}

TEST(CameraFollow, TheBirdStaysInViewForEveryReferenceShotOfEveryCampaignLevelAndTheViewReturns)
{
    int shots = 0;
    int outsideHomeView = 0; // steps where a camera left at the level's home view would have lost the bird
    int impactSteps = 0;
    int withNextBird = 0;
    int lateReturns = 0; // shots whose camera was still on its way home when the next bird was ready
    for (const CampaignLevel& entry : campaign().levels)
    {
        if (!entry.level.referenceShot)
            continue;
        SCOPED_TRACE(entry.level.id);
        ++shots;
        GameSession session(entry.level);
        CameraRig rig;
        const sf::Vector2u window(1280, 720);
        rig.reset(cameraFocusOf(session), window);
        const CameraView home = rig.view();
        const Watched w = watchShot(session, rig, window, entry.level.referenceShot->angleDeg,
                                    entry.level.referenceShot->speedMps, home, &outsideHomeView);
        EXPECT_EQ(w.birdOut, 0) << "steps before the first contact with the launched bird out of view, of " << w.steps;
        EXPECT_EQ(w.birdTooSmall, 0) << "steps with the bird drawn under " << kMinBirdPx << " px";
        EXPECT_EQ(w.pigOut, 0) << "steps after the impact with a pig near the action out of view, of " << w.impactSteps;
        EXPECT_EQ(w.closerThanHome, 0) << "steps in flight zoomed closer than the aiming view, of " << w.steps;
        impactSteps += w.impactSteps;
        EXPECT_NE(session.phase(), Phase::Flying) << "the world settles within two minutes";
        // The next bird is ready: the camera is at the level's home view already (it headed home once the action
        // stopped or the bird was due within CameraRig::kReturnS), and stays.
        // (At rest: less than half a pixel from home, and so on the next frame.)
        const auto offHomePx = [&rig, &home]
        {
            const sf::Vector2f off = rig.view().centreM - home.centreM;
            return std::hypot(off.x, off.y) * home.pixelsPerMetre +
                   std::abs(rig.view().pixelsPerMetre / home.pixelsPerMetre - 1.0f) * 1280.0f;
        };
        EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);
        const bool nextBird = session.phase() == Phase::Aiming;
        withNextBird += nextBird ? 1 : 0;
        if (!nextBird || offHomePx() >= 0.5f)
        {
            // The level is over (no bird to aim), or the world stopped at once (a falling block landed) less than
            // kReturnS after the camera set off: it is on its way, and stops within kReturnS.
            lateReturns += nextBird ? 1 : 0;
            for (int i = 0; i < static_cast<int>(std::ceil(CameraRig::kReturnS * 60.0)); ++i)
                rig.update(cameraFocusOf(session), 1.0 / 60.0);
        }
        EXPECT_LT(offHomePx(), 0.5f);
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
        const CameraView rest = rig.view();
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
        EXPECT_EQ(rig.view().centreM, rest.centreM) << "at rest: no more creeping";
    }
    EXPECT_EQ(shots, 50) << "every campaign level has a reference shot";
    // At rest when the next bird is ready, on all but the shots whose world stops at once (5-1, on the Moon: a falling
    // block lands 0.25 s after the camera set off; 1-4 since wood takes 50 N s: all is calm 1.48 s after the contact,
    // less than kReturnS after the last piece slowed down).
    EXPECT_GE(withNextBird, 30);
    EXPECT_LE(lateReturns, 2) << "of " << withNextBird << " shots with a next bird";
    // Following is really tested: a fixed camera would lose the bird on some of these shots.
    EXPECT_GT(outsideHomeView, 0);
    EXPECT_GT(impactSteps, 50 * 30);
}

TEST(CameraFollow, TheWhiteBirdsEggIsFollowedToItsLandingNotTheEmptiedBird)
{
    // 4-8 with a white bird at 45 degrees, 28 m/s, the egg laid 1.35 s out: the egg falls to the ground and rolls;
    // the emptied bird climbs away and is left out of the picture.
    LevelDef level = campaign().levels.at(campaign().indexOf("4-8").value()).level;
    level.birds = {"white"};
    GameSession session(level);
    CameraRig rig;
    rig.reset(cameraFocusOf(session), {1280, 720});
    session.launch(45.0, 28.0);
    int eggSteps = 0;
    int eggOut = 0;
    int birdFollowed = 0;
    for (int i = 0; i < 60 * 20 && session.phase() == Phase::Flying; ++i)
    {
        if (i == 80)
        {
            ASSERT_TRUE(session.activateAbility());
        }
        session.step();
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
        const sf::FloatRect visible = rig.camera().visibleWorld();
        for (const Entity& e : session.world().entities())
        {
            if (e.kind != EntityKind::Bird || !e.alive || e.body == nullptr)
                continue;
            if (!e.shotBird)
            {
                ++eggSteps;
                eggOut += inside(visible, positionOf(e)) ? 0 : 1;
            }
            else if (i > 80 + 60 && inside(visible, positionOf(e)))
                ++birdFollowed; // a second after the egg, the emptied bird is no longer in the picture
        }
    }
    EXPECT_GT(eggSteps, 60);
    EXPECT_EQ(eggOut, 0) << "of " << eggSteps << " steps with the egg in the world";
    EXPECT_EQ(birdFollowed, 0);
}

TEST(CameraFollow, TakingHoldOfTheBirdStopsACameraOnItsWayHome)
{
    // Panned away, then recentred: the way home has begun. A press on the bird holds the view where it is.
    GameSession session(firstFlight());
    CameraRig rig;
    rig.reset(cameraFocusOf(session), {1280, 720});
    const CameraView home = rig.view();
    rig.panPixels({300.0f, 0.0f});
    rig.recentre();
    rig.update(cameraFocusOf(session), 0.1);
    const CameraView underWay = rig.view();
    ASSERT_NE(underWay.centreM, home.centreM);
    rig.holdStill();
    for (int i = 0; i < 60; ++i)
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
    EXPECT_EQ(rig.view().centreM, underWay.centreM);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Manual);
    // At home and at rest, holding the bird changes nothing.
    rig.recentre();
    for (int i = 0; i < 60; ++i)
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
    rig.holdStill();
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);
    EXPECT_EQ(rig.view().centreM, home.centreM);
}

TEST(CameraFollow, AfterTheImpactThePigsNearTheActionStayInViewOnAGridOfShots)
{
    // Beyond the reference shots: five angles and two speeds on every campaign level.
    int shotsWithImpact = 0;
    for (const CampaignLevel& entry : campaign().levels)
    {
        SCOPED_TRACE(entry.level.id);
        for (const double angle : {10.0, 25.0, 40.0, 55.0, 70.0})
            for (const double share : {0.7, 1.0})
            {
                GameSession session(entry.level);
                const auto band = session.band();
                CameraRig rig;
                rig.reset(cameraFocusOf(session), {1280, 720});
                const Watched w =
                    watchShot(session, rig, {1280, 720}, angle, band->atFraction(share).speedMps, rig.view(), nullptr);
                EXPECT_EQ(w.pigOut, 0) << angle << " deg at " << share * 100 << " % pull";
                EXPECT_EQ(w.birdOut, 0) << angle << " deg at " << share * 100 << " % pull";
                shotsWithImpact += w.impactSteps > 0 ? 1 : 0;
            }
    }
    EXPECT_GT(shotsWithImpact, 150);
}

TEST(CameraControl, ZoomKeepsThePointUnderThePointerAndPanMovesTheWorldWithTheDrag)
{
    GameSession session(firstFlight());
    CameraRig rig;
    rig.reset(cameraFocusOf(session), {1280, 720});
    const sf::Vector2f pointer(900.0f, 300.0f);
    const sf::Vector2f before = rig.camera().toWorld(pointer);
    const float ppm = rig.view().pixelsPerMetre;
    rig.zoomAt(1.5f, pointer);
    EXPECT_NEAR(rig.view().pixelsPerMetre, 1.5f * ppm, 1e-3f);
    EXPECT_NEAR(rig.camera().toWorld(pointer).x, before.x, 1e-3f);
    EXPECT_NEAR(rig.camera().toWorld(pointer).y, before.y, 1e-3f);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Manual);

    // Dragging by (40, 25) px: the world point that was under the pointer is under the pointer's new place.
    const sf::Vector2f grabbed = rig.camera().toWorld(pointer);
    rig.panPixels({40.0f, 25.0f});
    EXPECT_NEAR(rig.camera().toWorld(pointer + sf::Vector2f(40.0f, 25.0f)).x, grabbed.x, 1e-3f);
    EXPECT_NEAR(rig.camera().toWorld(pointer + sf::Vector2f(40.0f, 25.0f)).y, grabbed.y, 1e-3f);

    // A manual view stays until recentred, then eases home.
    for (int i = 0; i < 30; ++i)
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Manual);
    rig.recentre();
    for (int i = 0; i < 240; ++i)
        rig.update(cameraFocusOf(session), 1.0 / 60.0);
    EXPECT_NEAR(rig.view().pixelsPerMetre, ppm, 0.01f * ppm);

    // The player cannot zoom into a close-up or lose the level in the sky.
    for (int i = 0; i < 50; ++i)
        rig.zoomAt(2.0f, pointer);
    EXPECT_LE(rig.view().pixelsPerMetre, camera_limits::kMaxPixelsPerMetre);
    for (int i = 0; i < 50; ++i)
        rig.zoomAt(0.5f, pointer);
    EXPECT_GE(rig.view().pixelsPerMetre, ppm / 4.0f - 1e-3f);
}

TEST(CameraControl, EventsMapToZoomPanAndHome)
{
    GameSession session(firstFlight());
    CameraRig rig;
    rig.reset(cameraFocusOf(session), {1280, 720});
    const float ppm = rig.view().pixelsPerMetre;
    CameraControls controls;

    sf::Event wheel{};
    wheel.type = sf::Event::MouseWheelScrolled;
    wheel.mouseWheelScroll.delta = 1.0f;
    wheel.mouseWheelScroll.x = 640;
    wheel.mouseWheelScroll.y = 360;
    EXPECT_TRUE(controls.handleEvent(wheel, rig, true));
    EXPECT_NEAR(rig.view().pixelsPerMetre, ppm * CameraControls::kWheelZoom, 1e-3f);

    sf::Event key{};
    key.type = sf::Event::KeyPressed;
    key.key.code = sf::Keyboard::Subtract;
    EXPECT_TRUE(controls.handleEvent(key, rig, true));
    EXPECT_NEAR(rig.view().pixelsPerMetre, ppm * CameraControls::kWheelZoom / CameraControls::kKeyZoom, 1e-3f);
    const float x = rig.view().centreM.x;
    key.key.code = sf::Keyboard::D;
    EXPECT_TRUE(controls.handleEvent(key, rig, true));
    EXPECT_NEAR(rig.view().centreM.x - x, CameraControls::kKeyPanPx / rig.view().pixelsPerMetre, 1e-3f);
    key.key.code = sf::Keyboard::Up; // aiming's, not the camera's
    EXPECT_FALSE(controls.handleEvent(key, rig, true));
    key.key.code = sf::Keyboard::Home;
    EXPECT_TRUE(controls.handleEvent(key, rig, true));
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);

    // A left press that would aim or fire an ability is not the camera's; a free one pans once it moves.
    sf::Event press{};
    press.type = sf::Event::MouseButtonPressed;
    press.mouseButton.button = sf::Mouse::Left;
    press.mouseButton.x = 700;
    press.mouseButton.y = 200;
    EXPECT_FALSE(controls.handleEvent(press, rig, false));
    EXPECT_FALSE(controls.panning());
    EXPECT_TRUE(controls.handleEvent(press, rig, true));
    sf::Event move{};
    move.type = sf::Event::MouseMoved;
    move.mouseMove.x = 701; // under the drag threshold: a click, not a pan
    move.mouseMove.y = 200;
    controls.handleEvent(move, rig, true);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Home);
    move.mouseMove.x = 760;
    controls.handleEvent(move, rig, true);
    EXPECT_EQ(rig.mode(), CameraRig::Mode::Manual);
}

TEST(CameraFit, AResizeKeepsTheLevelInViewWithoutStretching)
{
    for (const CampaignLevel& entry : campaign().levels)
    {
        GameSession session(entry.level);
        CameraRig rig;
        rig.reset(cameraFocusOf(session), {1280, 720});
        for (const sf::Vector2u window : windowShapes())
        {
            rig.resize(window);
            rig.update(cameraFocusOf(session), 1.0 / 60.0);
            const sf::FloatRect visible = rig.camera().visibleWorld();
            EXPECT_NEAR(visible.width / visible.height, static_cast<float>(window.x) / static_cast<float>(window.y),
                        1e-3f);
            const CameraFocus focus = cameraFocusOf(session);
            const WorldBox home = focus.home;
            EXPECT_TRUE(inside(visible, {home.left + 0.5f, home.bottom + 0.1f}))
                << entry.level.id << " " << window.x << "x" << window.y;
            // The whole level, or (wider than the smallest pig drawn 12 px tall allows) the slingshot's end of it.
            if (rig.homeLeavesLevelOut(focus))
                EXPECT_GE(rig.view().pixelsPerMetre * focus.smallestPigM, kMinPigPx - 1e-3f) << entry.level.id;
            else
                EXPECT_TRUE(inside(visible, {home.right - 0.5f, home.top - 0.5f}))
                    << entry.level.id << " " << window.x << "x" << window.y;
        }
    }
}

/// Every campaign level and every lesson.
std::vector<LevelDef> everyLevel()
{
    std::vector<LevelDef> levels;
    for (const CampaignLevel& entry : campaign().levels)
        levels.push_back(entry.level);
    for (const std::string& path : levelFilesIn(std::string(ABALIKE_SOURCE_DIR) + "/levels/lessons"))
        levels.push_back(loadLevel(path, Catalog::builtin()));
    return levels;
}

TEST(PullReach, AFullPullInEveryLaunchDirectionStaysInsideEveryLevelsAimingViewInEveryWindowShape)
{
    // The layout walk's windows and the camera tests' (a tall one among them), with the HUD's and the teaching
    // overlay's top and the ground line where large text lifts it.
    std::vector<sf::Vector2u> windows = windowShapes();
    windows.insert(windows.end(), {{1024, 768}, {1280, 400}});
    const std::vector<LevelDef> levels = everyLevel();
    ASSERT_GE(levels.size(), 59u);
    int checked = 0;
    for (const LevelDef& level : levels)
        for (const sf::Vector2u window : windows)
            for (const float topReserved : {camera_limits::kTopReserved, 0.4f})
                for (const float groundFromBottom : {camera_limits::kGroundFromBottom, 0.3f})
                {
                    // The teaching overlay at large text leaves the level less than half the window: the ground
                    // stays where the panels put it (a steep full pull may end below the window; the keys reach it).
                    const bool roomBelow = 1.0f - topReserved - groundFromBottom >= 0.45f;
                    SCOPED_TRACE(level.id + " in " + std::to_string(window.x) + "x" + std::to_string(window.y) +
                                 " top " + std::to_string(topReserved) + " ground " + std::to_string(groundFromBottom));
                    GameSession session(level);
                    CameraFocus focus = cameraFocusOf(session);
                    focus.topReserved = topReserved;
                    focus.groundFromBottom = groundFromBottom;
                    CameraRig rig;
                    rig.reset(focus, window);
                    const auto launch = session.launchPoint();
                    const sf::Vector2f pouch =
                        rig.camera().toScreen({static_cast<float>(launch.x), static_cast<float>(launch.y)});
                    const float pull = fullPullPx(window);
                    for (int angle = -10; angle <= 80; angle += 2)
                    {
                        // The pointer at a full pull: behind the pouch, against the launch (screen y points down).
                        const double a = angle * 3.14159265358979 / 180.0;
                        const sf::Vector2f hand = pouch + pull * sf::Vector2f(-static_cast<float>(std::cos(a)),
                                                                              static_cast<float>(std::sin(a)));
                        EXPECT_GE(hand.x, pull_reach::kMarginPx - 0.01f) << angle << " deg";
                        EXPECT_GE(hand.y, pull_reach::kMarginPx - 0.01f) << angle << " deg";
                        EXPECT_LE(hand.x, static_cast<float>(window.x) - pull_reach::kMarginPx + 0.01f) << angle;
                        if (roomBelow || angle <= 0)
                        {
                            EXPECT_LE(hand.y, static_cast<float>(window.y) - pull_reach::kMarginPx + 0.01f) << angle;
                        }
                        ++checked;
                    }
                    // Still the level: the slingshot and its stand in view, not the sky above it.
                    EXPECT_TRUE(inside(rig.camera().visibleWorld(),
                                       {static_cast<float>(launch.x), static_cast<float>(level.groundY)}));
                }
    EXPECT_GT(checked, 20000);
}

TEST(LabelPlacement, ALabelGoesNextToItsAnchorOffTheStructureWhenThereIsRoom)
{
    const sf::Vector2f window(1280.0f, 720.0f);
    const sf::Vector2f size(220.0f, 30.0f);
    // A tower right of the anchor, reaching high above it: above-right is taken, above-left is free.
    const std::vector<sf::FloatRect> tower{{600.0f, 200.0f, 200.0f, 400.0f}};
    const sf::Vector2f anchor(610.0f, 500.0f);
    const sf::Vector2f at = placeLabel(anchor, size, window, tower, 18.0f);
    EXPECT_EQ(coveredArea({at, size}, tower), 0.0f);
    EXPECT_LT(std::hypot(at.x + 0.5f * size.x - anchor.x, at.y + 0.5f * size.y - anchor.y), 200.0f) << "near";
    EXPECT_GE(at.x, 4.0f);

    // Walled in on every side within reach: the spot covering least, still inside the window.
    const std::vector<sf::FloatRect> everywhere{{0.0f, 0.0f, 1280.0f, 720.0f}};
    const sf::Vector2f forced = placeLabel({1270.0f, 10.0f}, size, window, everywhere, 18.0f);
    EXPECT_LE(forced.x + size.x, window.x - 4.0f + 1e-3f);
    EXPECT_GE(forced.y, 4.0f);
}

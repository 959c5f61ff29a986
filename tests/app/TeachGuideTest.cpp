// The guides (tutorial, lessons) and the path samples of the teaching overlay, on real sessions, without a window.
#include "teach/Guide.hpp"
#include "teach/PathHistory.hpp"

#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <regex>
#include <set>

namespace abalike::app
{
namespace
{

LevelDef sourceLevel(const std::string& relative)
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/" + relative, Catalog::builtin());
}

TEST(TeachGuides, EveryNumberInALessonsStepsIsRecomputedFromItsLevel)
{
    // The lesson guides' texts are built from the lesson level's slingshot, birds, materials and gravity. Every
    // number in them must be one of those values, recomputed here from first principles and rounded as the guide
    // rounds them, or the mathematics of a formula or an aim (1, 2, 30, 45, 60, 90).
    const std::regex number(R"((^|[^A-Za-z0-9_.])(\d+(\.\d+)?))");
    const auto fixed = [](double value, int decimals)
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
        return std::string(text);
    };
    int checked = 0;
    for (const LessonEntry& lesson : lessonList())
    {
        SCOPED_TRACE(lesson.id);
        const LevelDef level = sourceLevel("levels/lessons/" + lesson.file);
        std::set<std::string> allowed{"1", "2", "30", "45", "60", "90"};
        const BandDef band = levelBand(level, Catalog::builtin());
        const double energy = 0.5 * band.maxForceN * band.maxPullM;
        allowed.insert(fixed(energy, 0));
        allowed.insert(fixed(band.bandMassKg, 0));
        for (const char* name : {"red", "black"})
        {
            const double m = Catalog::builtin().findBird(name)->massKg;
            const double v = std::sqrt(2.0 * energy / (m + band.bandMassKg));
            allowed.insert(fixed(m, 0));
            allowed.insert(fixed(m + band.bandMassKg, 0));
            allowed.insert(fixed(v, 1));
            allowed.insert(fixed(m * v, 0));
            allowed.insert(fixed(100.0 * m / (m + band.bandMassKg), 0)); // the bird's share of E in %
        }
        allowed.insert(fixed(100.0 * std::sqrt((4.0 + band.bandMassKg) / (8.0 + band.bandMassKg)), 0));
        for (const char* material : {"ice", "wood", "stone"})
            allowed.insert(fixed(Catalog::builtin().findMaterial(material)->strengthNs, 0));
        allowed.insert(fixed(level.environment.gravity, 2));
        allowed.insert(fixed(9.81 / level.environment.gravity, 1));
        const std::optional<Guide> guide = guideFor(level, Catalog::builtin());
        ASSERT_TRUE(guide);
        std::vector<std::string> texts{guide->closing};
        for (const GuideStep& step : guide->steps)
            texts.push_back(step.text);
        for (const std::string& text : texts)
            for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
            {
                ++checked;
                EXPECT_TRUE(allowed.contains((*it)[2].str())) << (*it)[2].str() << " in \"" << text << "\"";
            }
    }
    EXPECT_GE(checked, 15);
}

TEST(TeachGuides, EveryLessonHasALevelThatLoadsAndAGuide)
{
    ASSERT_EQ(lessonList().size(), 8u); // one per concept the campaign teaches, and predict-then-launch
    for (const LessonEntry& lesson : lessonList())
    {
        const LevelDef level = sourceLevel("levels/lessons/" + lesson.file);
        EXPECT_EQ(level.id, lesson.id);
        EXPECT_FALSE(level.lesson.empty()) << lesson.id << " says what it teaches";
        const std::optional<Guide> guide = guideFor(level, Catalog::builtin());
        ASSERT_TRUE(guide) << lesson.id;
        EXPECT_GE(guide->steps.size(), 2u);
        EXPECT_FALSE(guide->closing.empty());
    }
    const auto withId = [](const std::string& id)
    {
        LevelDef level;
        level.id = id;
        return guideFor(level, Catalog::builtin());
    };
    EXPECT_TRUE(withId("tutorial"));
    EXPECT_FALSE(withId("1-1"));
    EXPECT_FALSE(withId("lesson-unknown"));
}

/// The mass lesson's numbers are its own slingshot's: 1 250 J at full pull, red 25.0 m/s, black 17.7 m/s.
TEST(TeachGuides, TheMassLessonTellsTheSharedEnergyWithItsOwnNumbers)
{
    const LevelDef level = sourceLevel("levels/lessons/lesson-mass.json");
    const std::optional<Guide> guide = guideFor(level, Catalog::builtin());
    ASSERT_TRUE(guide);
    ASSERT_EQ(guide->steps.size(), 3u);
    const BandDef band = levelBand(level, Catalog::builtin());
    const double energy = 0.5 * band.maxForceN * band.maxPullM;
    const double red = std::sqrt(2.0 * energy / (4.0 + band.bandMassKg));
    const double black = std::sqrt(2.0 * energy / (8.0 + band.bandMassKg));
    EXPECT_NEAR(red, 25.0, 1e-9);
    const std::string& second = guide->steps[1].text;
    EXPECT_NE(second.find("same 5625 J now moves 22 kg instead of 18 kg"), std::string::npos) << second;
    EXPECT_NE(second.find("leaves at 22.6 m/s instead of 25.0 m/s"), std::string::npos) << second;
    EXPECT_NE(second.find("= 90 %) and takes 36 % of the energy, not 22 %"), std::string::npos) << second;
    const std::string& third = guide->steps[2].text;
    EXPECT_NE(third.find(std::to_string(static_cast<int>(std::lround(8.0 * black))) + " N\u00B7s for the heavy"),
              std::string::npos)
        << third;
    EXPECT_NE(third.find("100 N\u00B7s for the light"), std::string::npos) << third;
}

/// The angle lesson, played: each step is done only by doing what it asks.
TEST(TeachGuides, TheAngleLessonAdvancesOnlyWhenThePlayerDoesTheStep)
{
    GameSession session(sourceLevel("levels/lessons/lesson-angle.json"));
    GuideRunner runner;
    runner.start(*guideFor(sourceLevel("levels/lessons/lesson-angle.json"), Catalog::builtin()));
    GuideContext context;
    context.session = &session;
    runner.update(context);
    EXPECT_EQ(runner.step(), 0u);
    context.chartOn = true; // G
    runner.update(context);
    EXPECT_EQ(runner.step(), 1u);
    const auto play = [&](double angle)
    {
        session.launch(angle, session.maxLaunchSpeed());
        while (session.phase() == Phase::Flying)
            session.step();
        runner.update(context);
    };
    play(75.0); // not what step 2 asks (30 degrees or lower), and short of the pig
    EXPECT_EQ(runner.step(), 1u);
    play(30.0);
    EXPECT_EQ(runner.step(), 2u);
    play(75.0);
    EXPECT_EQ(runner.step(), 3u);
    EXPECT_NE(session.phase(), Phase::Won);
    play(45.0); // full power at 45 degrees reaches the pig
    EXPECT_EQ(session.phase(), Phase::Won);
    EXPECT_EQ(runner.step(), 4u);
}

TEST(TeachGuides, TheTutorialsLevelOutlastsItsSteps)
{
    // The tutorial's own level: no first shot of a fan of aims and pulls defeats all three pigs, so the level is
    // still on when the guide asks for the second launch (1-1, which it once borrowed, ended on step 5).
    const LevelDef level = sourceLevel("levels/lessons/tutorial.json");
    EXPECT_EQ(level.id, "tutorial");
    EXPECT_GE(level.birds.size(), 6u);
    for (double angle = 0.0; angle <= 70.0; angle += 5.0)
        for (double speed = 12.0; speed <= 30.0; speed += 3.0)
        {
            const auto session = simulateShots(level, {{angle, speed}});
            EXPECT_GE(session->pigsRemaining(), 1) << angle << " deg, " << speed << " m/s";
        }
}

TEST(TeachGuides, TheTutorialFollowsTheAim)
{
    GameSession session(sourceLevel("levels/lessons/tutorial.json"));
    GuideRunner runner;
    runner.start(tutorialGuide());
    GuideContext context;
    context.session = &session;
    AimReadout aim;
    aim.angleDeg = 45.0;
    aim.speedMps = 15.0;
    context.aim = aim;
    runner.update(context);
    EXPECT_EQ(runner.step(), 0u);
    context.aim->angleDeg = 50.0;
    runner.update(context);
    EXPECT_EQ(runner.step(), 1u);
    context.aim->speedMps = 20.0;
    runner.update(context);
    EXPECT_EQ(runner.step(), 2u);
    context.overlayOn = true; // T before launching does not skip the launch step
    runner.update(context);
    EXPECT_EQ(runner.step(), 2u);
    session.launch(50.0, 20.0);
    runner.update(context);
    EXPECT_EQ(runner.step(), 4u); // launched, and the overlay was already on
}

TEST(TeachPaths, SamplesCarryVelocitiesFromTheFlownPath)
{
    // A parabola sampled every 1/60 s: central differences give its velocity to O(dt^2), exactly for a parabola.
    std::vector<TrackPoint> path;
    for (int i = 0; i <= 60; ++i)
    {
        const double t = i / 60.0;
        path.push_back({t, {10.0 * t, 10.0 * t - 4.905 * t * t}});
    }
    const std::vector<PathSample> samples = samplesOf(path);
    ASSERT_EQ(samples.size(), path.size());
    for (std::size_t i = 1; i + 1 < samples.size(); ++i)
    {
        EXPECT_NEAR(samples[i].vx, 10.0, 1e-9);
        EXPECT_NEAR(samples[i].vy, 10.0 - 9.81 * samples[i].t, 1e-9);
    }
    // A contact point at a step's own time (zero interval) borrows its neighbour's velocity instead of dividing by 0.
    path.push_back(path.back());
    const std::vector<PathSample> withRepeat = samplesOf(path);
    EXPECT_TRUE(std::isfinite(withRepeat.back().vx));
    EXPECT_TRUE(samplesOf({}).empty());
}

TEST(TeachPaths, TrailsKeepTheLastFiveShotsAcrossRestartsAndForgetAnotherLevel)
{
    GameSession session(sourceLevel("levels/1-1-first-flight.json"));
    ShotTrails trails;
    trails.onLevelStart(session);
    for (int shot = 0; shot < 7; ++shot)
    {
        if (session.currentBird() == nullptr || session.finished())
        {
            session.restart();
            trails.onLevelStart(session);
            EXPECT_FALSE(trails.newestIsCurrentShot()); // after a restart every kept path is an earlier one
        }
        session.launch(20.0 + shot, 8.0);
        while (session.phase() == Phase::Flying)
        {
            session.step();
            trails.update(session);
        }
        EXPECT_TRUE(trails.newestIsCurrentShot());
    }
    ASSERT_EQ(trails.paths().size(), ShotTrails::kMaxPaths);
    EXPECT_EQ(trails.paths().back().name, "shot 7");
    EXPECT_EQ(trails.paths().front().name, "shot 3");
    EXPECT_GT(trails.paths().back().samples.size(), 10u);
    // The newest kept path is the flown path, point for point.
    const std::vector<TrackPoint>& flown = session.shots().back().actualPath;
    ASSERT_EQ(trails.paths().back().samples.size(), flown.size());
    EXPECT_DOUBLE_EQ(trails.paths().back().samples.back().x, flown.back().position.x);

    GameSession other(sourceLevel("levels/1-2-the-long-shot.json"));
    trails.onLevelStart(other);
    EXPECT_TRUE(trails.paths().empty());
}

} // namespace
} // namespace abalike::app

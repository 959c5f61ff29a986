#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/ShotFeedback.hpp>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <regex>

namespace abalike
{
namespace
{

LevelDef campaignLevel(const std::string& name)
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/" + name, Catalog::builtin());
}

/// A stone cube floating in zero gravity, hit head-on by the red bird (4 kg) at 20 m/s: an isolated 1-D collision.
LevelDef zeroGravityCube()
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "zero g", "environment": {"gravity": 0.0},
        "ground": {"y": 0.0}, "slingshot": {"x": 0.0, "y": 5.0, "max_force_n": 1200, "band_mass_kg": 0}, "birds": ["red", "red"],
        "blocks": [{"material": "stone", "x": 10.0, "y": 5.0, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.35}], "stars": [1, 2, 3]})",
                      "zero-g.json", Catalog::builtin());
}

/// The issue's test: on a level with drag and wind, launch energy = kinetic + potential + drag loss at first contact.
TEST(ShotEnergy, BalanceClosesOnADragAndWindLevel)
{
    for (const char* name : {"3-1-tailwind.json", "3-5-headwind.json", "3-4-gusts.json", "3-3-breathing-wind.json"})
    {
        const LevelDef level = campaignLevel(name);
        const auto session = simulateShots(level, {{level.referenceShot->angleDeg, level.referenceShot->speedMps}});
        const ShotRecord& shot = session->shots().at(0);
        ASSERT_TRUE(shot.actualContact) << name;
        ASSERT_TRUE(shot.energy) << name;
        const FlightEnergy& e = *shot.energy;
        const double launch = e.launchKineticJ + e.launchPotentialJ;
        EXPECT_GT(e.dragLossJ, 0.05 * launch) << name; // the air takes a real share
        EXPECT_NEAR(e.balanceResidualJ(), 0.0, 1e-8 * launch) << name;
        // Potential energy uses level coordinates: the launch is at the slingshot's height.
        EXPECT_DOUBLE_EQ(e.launchPotentialJ, 4.0 * level.environment.gravity * level.slingshot.y);
        EXPECT_DOUBLE_EQ(e.launchKineticJ, 0.5 * 4.0 * shot.speedMps * shot.speedMps);
        // The state it is taken at is the bird's at its first contact (the world's contact lies on the step's
        // chord, within the chord's sag of the curved path).
        EXPECT_NEAR(e.state.position.x, shot.actualContact->x, 1e-3) << name;
        EXPECT_NEAR(e.state.position.y, shot.actualContact->y, 1e-3) << name;
    }
}

TEST(ShotEnergy, NoneWhenAnAbilityFiredBeforeContact)
{
    const LevelDef level = campaignLevel("4-7-hard-hats.json"); // yellow birds: boost
    const auto session = simulateShots(level, {{35.0, 20.0, 0.3}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.ability);
    EXPECT_TRUE(shot.ability->beforeContact);
    EXPECT_FALSE(shot.energy);
}

TEST(FirstImpact, HeadOnIntoAFloatingCubeConservesMomentumWithTheMaterialsRestitution)
{
    const auto session = simulateShots(zeroGravityCube(), {{0.0, 20.0}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.impact);
    const FirstImpact& hit = *shot.impact;
    EXPECT_EQ(hit.bodyKind, EntityKind::Block);
    EXPECT_EQ(hit.bodyIndex, 0);
    EXPECT_EQ(hit.bodyType, "stone");
    EXPECT_DOUBLE_EQ(hit.bodyMassKg, 240.0); // 240 kg/m^2 x 1 m^2
    EXPECT_NEAR(hit.birdMassKg, 4.0, 1e-5);
    EXPECT_NEAR(hit.birdBefore.vx, 20.0, 1e-4);
    EXPECT_EQ(hit.bodyBefore.vx, 0.0);
    EXPECT_NEAR(hit.normal.x, 1.0, 1e-6);
    // Box2D mixes restitution as the larger of the two: the red bird's 0.3 against stone's 0.05.
    ASSERT_TRUE(hit.restitution());
    EXPECT_NEAR(*hit.restitution(), 0.3, 0.01);
    // 1-D collision with e = 0.3: v_bird' = (m1 - e m2) v / (m1 + m2), v_cube' = (1 + e) m1 v / (m1 + m2).
    EXPECT_NEAR(hit.birdAfter.vx, (4.0 - 0.3 * 240.0) * 20.0 / 244.0, 0.05);
    EXPECT_NEAR(hit.bodyAfter.vx, 1.3 * 4.0 * 20.0 / 244.0, 0.005);
    EXPECT_NEAR(hit.momentumAfter().x, hit.momentumBefore().x, 1e-5 * hit.momentumBefore().x);
    EXPECT_NEAR(hit.kineticBeforeJ(), 800.0, 0.01);
    EXPECT_LT(hit.kineticAfterJ(), hit.kineticBeforeJ());
    // The damage is the impulse the cube took: its change of momentum.
    EXPECT_NEAR(hit.damageNs, 240.0 * hit.bodyAfter.vx, 0.02 * hit.damageNs);
    const Entity& cube = *std::find_if(session->world().entities().begin(), session->world().entities().end(),
                                       [](const Entity& e) { return e.kind == EntityKind::Block; });
    EXPECT_NEAR(cube.maxHealth - cube.health, hit.damageNs, 1e-6 * hit.damageNs);
}

TEST(FirstImpact, NoneWhenTheFirstContactIsTheGround)
{
    const auto session = simulateShots(campaignLevel("1-1-first-flight.json"), {{10.0, 8.0}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.firstTouched);
    EXPECT_EQ(*shot.firstTouched, EntityKind::Ground);
    EXPECT_FALSE(shot.impact);
    EXPECT_TRUE(shot.energy); // the balance is still there
}

TEST(FirstImpact, OnAPigNamesItsIndex)
{
    const LevelDef level = campaignLevel("1-1-first-flight.json");
    // Straight at the medium pig on the ground between the second tower's columns is blocked; aim over the first
    // tower onto the small pig on top of the second.
    const auto session = simulateShots(level, {{30.0, 18.0}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.impact);
    if (shot.impact->bodyKind == EntityKind::Block)
        EXPECT_EQ(level.blocks.at(static_cast<std::size_t>(shot.impact->bodyIndex)).material, shot.impact->bodyType);
    else
        EXPECT_EQ(level.pigs.at(static_cast<std::size_t>(shot.impact->bodyIndex)).type, shot.impact->bodyType);
}

TEST(ShotFeedback, SentencesCarryTheShotsNumbers)
{
    const LevelDef windy = campaignLevel("3-5-headwind.json");
    const auto session = simulateShots(windy, {{windy.referenceShot->angleDeg, windy.referenceShot->speedMps}});
    const std::vector<std::string> lines = shotFeedback(windy, Catalog::builtin(), session->shots().at(0));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NE(lines[0].find("momentum"), std::string::npos) << lines[0];
    EXPECT_NE(lines[1].find("wind moved the landing point"), std::string::npos) << lines[1];
    EXPECT_NE(lines[1].find("back"), std::string::npos) << lines[1]; // a headwind

    const LevelDef vacuum = campaignLevel("5-1-the-moon.json");
    const auto moon = simulateShots(vacuum, {{40.0, 9.0}});
    const std::vector<std::string> moonLines = shotFeedback(vacuum, Catalog::builtin(), moon->shots().at(0));
    ASSERT_FALSE(moonLines.empty());
    EXPECT_NE(moonLines.back().find("g = 1.62"), std::string::npos) << moonLines.back();
}

/// Every number of a sentence, in order.
std::vector<double> numbersIn(const std::string& text)
{
    static const std::regex number(R"(-?\d+(\.\d+)?)");
    std::vector<double> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
        out.push_back(std::stod(it->str()));
    return out;
}

TEST(ShotFeedback, EveryNumberOfTheVacuumSentenceIsTheClosedForm)
{
    // From height h at speed v and angle a in vacuum: back at the launch height v^2 sin 2a / g; down to the ground
    // v cos a (v sin a + sqrt(v^2 sin^2 a + 2 g h)) / g; the best angle atan(v / sqrt(v^2 + 2 g h)) with range
    // v sqrt(v^2 + 2 g h) / g; from the ground, 45 degrees and v^2 / g. The sentence must state both heights, since
    // the lessons' v^2 sin 2a / g holds only back at the launch height.
    const LevelDef moonLevel = campaignLevel("5-1-the-moon.json");
    const double v = 9.0;
    const double a = 40.0 * M_PI / 180.0;
    const double g = 1.62;
    const double h = moonLevel.slingshot.y - moonLevel.groundY;
    const auto moon = simulateShots(moonLevel, {{40.0, v}});
    const std::string sentence = shotFeedback(moonLevel, Catalog::builtin(), moon->shots().at(0)).back();
    const std::vector<double> n = numbersIn(sentence);
    const double range = v * std::cos(a) * (v * std::sin(a) + std::sqrt(std::pow(v * std::sin(a), 2) + 2 * g * h)) / g;
    const double root = std::sqrt(v * v + 2 * g * h);
    // "With no air (g = G m/s²), A° at V m/s brings the bird's centre back to the launch height L m away and down to
    // the ground, H m lower, R m away; from that height B° reaches the furthest, F m (from the ground: 45°, v²/g = D
    // m)."
    ASSERT_EQ(n.size(), 10u) << sentence;
    EXPECT_NEAR(n[0], g, 0.005);
    EXPECT_NEAR(n[1], 40.0, 0.05);
    EXPECT_NEAR(n[2], v, 0.05);
    EXPECT_NEAR(n[3], v * v * std::sin(2 * a) / g, 0.06) << sentence;
    EXPECT_NEAR(n[4], h, 0.05) << sentence;
    EXPECT_NEAR(n[5], range, 0.06) << sentence;
    EXPECT_NEAR(n[6], std::atan(v / root) * 180.0 / M_PI, 0.06) << sentence;
    EXPECT_NEAR(n[7], v * root / g, 0.06) << sentence;
    EXPECT_EQ(n[8], 45.0);
    EXPECT_NEAR(n[9], v * v / g, 0.06) << sentence;
}

TEST(ShotFeedback, TheDragSentenceCountsTheLaunchEnergyTheEnergyPanelShows)
{
    // "Air drag took L J of the E J the bird launched with (kinetic + potential, P %)": E = 1/2 m v^2 + m g y, the
    // launch energy the energy panel shows beside the sentence (one number on the screen), P = 100 L / E, and L is
    // the energy balance's drag loss at the first contact.
    const LevelDef air = campaignLevel("3-2-thick-air.json");
    const auto session = simulateShots(air, {{air.referenceShot->angleDeg, air.referenceShot->speedMps}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.energy.has_value());
    std::string sentence;
    for (const std::string& line : shotFeedback(air, Catalog::builtin(), shot))
        if (line.find("Air drag took") != std::string::npos)
            sentence = line;
    ASSERT_FALSE(sentence.empty());
    const std::vector<double> n = numbersIn(sentence);
    ASSERT_GE(n.size(), 3u) << sentence;
    const double launch = 0.5 * 4.0 * shot.speedMps * shot.speedMps + shot.energy->launchPotentialJ;
    EXPECT_GT(shot.energy->launchPotentialJ, 1.0) << "the test tells the two launch energies apart";
    EXPECT_NEAR(n[0], shot.energy->dragLossJ, 0.5) << sentence;
    EXPECT_NEAR(n[1], launch, 0.5) << sentence;
    EXPECT_NEAR(n[2], 100.0 * shot.energy->dragLossJ / launch, 0.5) << sentence;
}

} // namespace
} // namespace abalike

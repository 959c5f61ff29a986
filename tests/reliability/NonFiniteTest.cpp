#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>
#include <box2d/box2d.h>
#include <gtest/gtest.h>
#include <limits>

namespace abalike
{
namespace
{

/// NaN and infinity must be stopped where they enter: a level file, a launch. These tests feed them in at each
/// boundary the core has and expect a clear error instead of a world full of NaN.

const char* const kLevel = R"({
  "format": 1, "id": "t", "title": "T",
  "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red"],
  "blocks": [{"material": "wood", "x": 12, "y": 0.5, "w": 1, "h": 1}],
  "pigs": [{"type": "small", "x": 10, "y": 0.25}]
})";

struct BadNumber
{
    const char* name;
    const char* field; ///< text in kLevel to replace
    const char* value;
};

class NonFiniteLevelNumbers : public ::testing::TestWithParam<BadNumber>
{
};

TEST_P(NonFiniteLevelNumbers, AreLoadErrors)
{
    std::string text = kLevel;
    const std::string field = GetParam().field;
    const auto at = text.find(field);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, field.size(), field.substr(0, field.find(':') + 2) + GetParam().value);
    try
    {
        parseLevel(text, "level.json", Catalog::builtin());
        FAIL() << "loaded a level with " << GetParam().value;
    }
    catch (const LevelLoadError& e)
    {
        ASSERT_FALSE(e.issues().empty());
        EXPECT_NE(e.issues()[0].format().find("level.json:"), std::string::npos) << e.issues()[0].format();
    }
}

INSTANTIATE_TEST_SUITE_P(Values, NonFiniteLevelNumbers,
                         ::testing::Values(BadNumber{"SlingshotNaN", "\"x\": 0", "NaN"},
                                           BadNumber{"SlingshotInfinity", "\"x\": 0", "Infinity"},
                                           BadNumber{"BlockOverflow", "\"x\": 12", "1e400"},
                                           BadNumber{"BlockMinusOverflow", "\"x\": 12", "-1e400"},
                                           BadNumber{"PigNan", "\"y\": 0.25", "nan"},
                                           BadNumber{"BlockWidthHuge", "\"w\": 1", "1e308"},
                                           BadNumber{"PigTiny", "\"y\": 0.25", "-1e-400"}),
                         [](const ::testing::TestParamInfo<BadNumber>& info) { return std::string(info.param.name); });

TEST(NonFinite, LaunchRejectsNaNAndInfinity)
{
    const LevelDef level = parseLevel(kLevel, "level.json", Catalog::builtin());
    GameSession session(level);
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(session.launch(kNaN, 10.0), LaunchError);
    EXPECT_THROW(session.launch(30.0, kNaN), LaunchError);
    EXPECT_THROW(session.launch(30.0, kInf), LaunchError);
    EXPECT_THROW(session.launch(-kInf, 10.0), LaunchError);
    EXPECT_EQ(session.phase(), Phase::Aiming) << "a refused launch leaves the bird in the slingshot";
    session.launch(30.0, 10.0);
    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_FALSE(session.world().hasNonFiniteState());
}

TEST(NonFinite, AWorldThatGoesNonFiniteIsResetAndThePlayerIsTold)
{
    const LevelDef level = parseLevel(kLevel, "level.json", Catalog::builtin());
    GameSession session(level);
    session.launch(30.0, 10.0);
    for (int i = 0; i < 10; ++i)
        session.step();
    // Stands in for a body Box2D lets escape: nothing in a valid level does this on its own.
    for (const Entity& e : session.world().entities())
        if (e.kind == EntityKind::Block && e.body != nullptr)
            e.body->SetLinearVelocity(b2Vec2(std::numeric_limits<float>::quiet_NaN(), 0.0f));
    session.step();
    EXPECT_FALSE(session.world().hasNonFiniteState());
    EXPECT_EQ(session.phase(), Phase::Aiming);
    EXPECT_EQ(session.birdsUsed(), 0) << "the level starts over";
    EXPECT_FALSE(session.notice().empty());
    session.launch(30.0, 10.0); // and it plays on
}

TEST(NonFinite, SimulatedShotsRejectNaN)
{
    const LevelDef level = parseLevel(kLevel, "level.json", Catalog::builtin());
    EXPECT_THROW(simulateShots(level, {{std::numeric_limits<double>::quiet_NaN(), 10.0}}), LaunchError);
}

} // namespace
} // namespace abalike

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <abalike/world/Catalog.hpp>
#include <gtest/gtest.h>
#include <string>

namespace abalike
{
namespace
{

LevelDef levelWithTheme(const std::string& extra)
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "T", "slingshot": {"x": 0, "y": 1.5}, "birds": ["red"],
        "pigs": [{"x": 20, "y": 0.25}])" +
                          extra + "}",
                      "t.json", Catalog::builtin());
}

TEST(WorldTheme, TheLevelsGravityPicksTheWorldWithinFivePercent)
{
    EXPECT_EQ(levelTheme(levelWithTheme("")), WorldTheme::Earth);
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 1.62})")), WorldTheme::Moon);
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 3.8})")), WorldTheme::Mars); // 2.4 % off
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 1.35})")), WorldTheme::Titan);
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 24.0})")), WorldTheme::Jupiter); // 3.2 % off
    // Between worlds, and just outside 5 %: Earth's look.
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 6.0})")), WorldTheme::Earth);
    EXPECT_EQ(levelTheme(levelWithTheme(R"(, "environment": {"gravity": 3.5})")), WorldTheme::Earth); // 5.7 % off Mars
}

TEST(WorldTheme, AThemeInTheFileWinsAndRoundTrips)
{
    const LevelDef moonOnEarth = levelWithTheme(R"(, "theme": "moon")");
    EXPECT_EQ(levelTheme(moonOnEarth), WorldTheme::Moon);
    const std::string written = writeLevelJson(moonOnEarth, "");
    EXPECT_NE(written.find("\"theme\": \"moon\""), std::string::npos) << written;
    EXPECT_EQ(parseLevel(written, "t.json", Catalog::builtin()), moonOnEarth);
    // Without one, nothing is written: format 1 files stay as they were.
    EXPECT_EQ(writeLevelJson(levelWithTheme(""), "").find("theme"), std::string::npos);
}

TEST(WorldTheme, AnUnknownThemeIsAnErrorThatListsTheWorlds)
{
    try
    {
        levelWithTheme(R"(, "theme": "venus")");
        FAIL() << "venus was accepted";
    }
    catch (const LevelLoadError& e)
    {
        EXPECT_NE(std::string(e.what()).find("/theme: expected the world the scenery shows: \"earth\", \"moon\", "
                                             "\"mars\", \"titan\" or \"jupiter\", got \"venus\""),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(levelWithTheme(R"(, "theme": 3)"), LevelLoadError);
}

} // namespace
} // namespace abalike

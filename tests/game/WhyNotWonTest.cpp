#include <abalike/design/WhyNotWon.hpp>
#include <abalike/level/LevelIO.hpp>
#include <gtest/gtest.h>

using namespace abalike;

namespace
{

LevelDef levelWith(const std::string& blocks, const std::string& pigs, const std::string& slingshot = "")
{
    return parseLevel(R"({"format": 1, "id": "w", "title": "Why", "slingshot": {"x": 0, "y": 1.5)" + slingshot +
                          R"(}, "birds": ["red"], "blocks": [)" + blocks + R"(], "pigs": [)" + pigs + "]}",
                      "why.json", Catalog::builtin());
}

} // namespace

TEST(WhyNotWon, APigUnderAStoneRoofIsShieldedByWhatEveryPathToItHitsFirst)
{
    // Stone walls and a stone roof round a helmet pig: every launch that would reach it hits the nearer wall, which
    // takes 300 N·s, more than the red bird's 4 kg x 30 m/s.
    const LevelDef stone = levelWith(R"({"material": "stone", "x": 16, "y": 2, "w": 1, "h": 4},
        {"material": "stone", "x": 19.5, "y": 4.25, "w": 8, "h": 0.5},
        {"material": "stone", "x": 23, "y": 2, "w": 1, "h": 4})",
                                     R"({"type": "helmet", "x": 20, "y": 0.35})");
    EXPECT_EQ(whyPigSurvives(stone, Catalog::builtin(), 0),
              "shielded by block 0 (stone): the launches that would reach it hit that first, and stone takes 300 "
              "N\u00B7s, more than the red bird's 120 at full pull");
    // The same in wood: named, without the comparison (the bird could break wood).
    LevelDef wood = stone;
    for (BlockDef& block : wood.blocks)
        block.material = "wood";
    const std::string why = whyPigSurvives(wood, Catalog::builtin(), 0);
    EXPECT_EQ(why.rfind("shielded by block 0 (wood)", 0), 0u) << why;
    EXPECT_EQ(why.find("more than"), std::string::npos) << why;
}

TEST(WhyNotWon, APigNoLaunchComesNearIsOutOfReach)
{
    // A weak band (300 N: the red bird leaves at 12.2 m/s) and a pig 25 m away; the reader's reach check would
    // refuse the file, so the level is built in code.
    LevelDef level =
        levelWith("", R"({"type": "small", "x": 8, "y": 0.25})", R"(, "max_force_n": 300, "band_mass_kg": 0)");
    level.pigs.push_back({"small", 25.0, 0.25});
    const std::string why = whyPigSurvives(level, Catalog::builtin(), 1);
    EXPECT_EQ(why.rfind("out of reach (at full pull the red bird's nearest path passes ", 0), 0u) << why;
    EXPECT_TRUE(whyPigSurvives(level, Catalog::builtin(), 7).empty());
}

#include "../SanitizerBuild.hpp"
#include "RandomLevel.hpp"
#include "save/TempDir.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/world/Catalog.hpp>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace abalike
{
namespace
{

const std::filesystem::path kLevels = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels";
const std::filesystem::path kSchema = kLevels / "schema" / "level.schema.json";

/// The campaign's levels and the lessons (whose claims include forms no campaign level uses), relative to levels/.
std::vector<std::string> campaignLevels()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kLevels))
        if (entry.path().extension() == ".json" && entry.path().filename() != "campaign.json")
            names.push_back(entry.path().filename().string());
    for (const auto& entry : std::filesystem::directory_iterator(kLevels / "lessons"))
        if (entry.path().extension() == ".json")
            names.push_back("lessons/" + entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

using test::readText;

/// Loads what the writer wrote, geometry problems or not (random levels overlap by chance).
LevelDef reread(const std::string& text, const std::string& name)
{
    return parseLevelForEditing(text, name, Catalog::builtin()).level;
}

class CampaignLevelWriter : public ::testing::TestWithParam<std::string>
{
};

TEST_P(CampaignLevelWriter, SaveLoadSaveIsByteIdenticalAndLosesNothing)
{
    const std::string path = (kLevels / GetParam()).string();
    const LevelDef level = loadLevel(path, Catalog::builtin());
    const std::string first = writeLevelJson(level, "schema/level.schema.json");
    LevelDef again = parseLevel(first, path, Catalog::builtin()); // still passes every check
    EXPECT_EQ(again, level);
    EXPECT_EQ(writeLevelJson(again, "schema/level.schema.json"), first);
}

TEST_P(CampaignLevelWriter, KeepsTheHandWrittenKeyOrder)
{
    // The writer's top-level keys appear in the same order as in the designer's file.
    const std::string hand = readText(kLevels / GetParam());
    const LevelDef level = loadLevel((kLevels / GetParam()).string(), Catalog::builtin());
    const std::string written = writeLevelJson(level, "schema/level.schema.json");
    std::size_t last = 0;
    for (const char* key : {"\"$schema\"", "\"format\"", "\"id\"", "\"title\"", "\"episode\"", "\"concept\"",
                            "\"hints\"", "\"slingshot\"", "\"birds\"", "\"blocks\"", "\"pigs\"", "\"terrain\"",
                            "\"environment\"", "\"stars\"", "\"time_limit_s\"", "\"reference_shot\""})
    {
        const bool inHand = hand.find(std::string("\n  ") + key) != std::string::npos;
        const std::size_t at = written.find(std::string("\n  ") + key);
        if (!inHand)
            continue;
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, last) << key;
        last = at;
    }
}

INSTANTIATE_TEST_SUITE_P(Levels, CampaignLevelWriter, ::testing::ValuesIn(campaignLevels()),
                         [](const ::testing::TestParamInfo<std::string>& info)
                         {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return c == '-' || c == '/'; }, '_');
                             return name;
                         });

TEST(LevelWriter, GeneratedLevelsRoundTripExactly)
{
    test::RandomLevel random(20240601);
    const int count = test::kSanitizerBuild ? 30 : 120;
    for (int i = 0; i < count; ++i)
    {
        SCOPED_TRACE("level " + std::to_string(i));
        const LevelDef level = random.next();
        const std::string first = writeLevelJson(level, "schema/level.schema.json");
        LevelDef again;
        ASSERT_NO_THROW(again = reread(first, "generated.json")) << first;
        again.sourcePath = level.sourcePath;
        EXPECT_EQ(again, level) << first;
        EXPECT_EQ(writeLevelJson(again, "schema/level.schema.json"), first);
    }
}

TEST(LevelWriter, AnyGustPhaseIsStableAfterOneSave)
{
    // Phases live in radians and are written in degrees: one save may round the last digits, never a second.
    LevelDef level;
    level.id = "p";
    level.title = "p";
    level.birds = {"red"};
    level.pigs = {{"small", 10, 0.25}};
    level.environment.airDensity = 1.2;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    gusts.amplitudeX = 3;
    for (const double rad : {0.1, 1.0, 2.0 / 3.0, -3.0, 6.283185307179586, 1e-9})
    {
        gusts.phaseRad = rad;
        level.environment.gusts = gusts;
        const std::string first = writeLevelJson(level, "s");
        const LevelDef again = reread(first, "phase.json");
        EXPECT_NEAR(again.environment.gusts->phaseRad, rad, 1e-10); // 12 digits of degrees
        EXPECT_EQ(writeLevelJson(again, "s"), first);
    }
}

TEST(LevelWriter, WritesTheDocumentedLayout)
{
    LevelDef level;
    level.id = "demo";
    level.title = "A \"quoted\" title";
    level.sandbox = true;
    level.birds = {"red", "custom"};
    level.customBird = CustomBirdDef{0.145, 0.074, 0.35};
    level.blocks.push_back({BlockShape::Box, "stone", 22.0, 0.25, 3.0, 0.5, 0.0, 0.1});
    level.blocks.push_back({BlockShape::Circle, "wood", 1.0 / 3.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    level.blocks.push_back({BlockShape::HollowBox, "ice", 5.0, 1.0, 2.0, 2.0, -15.0, 0.2});
    level.environment.gravity = 1.62;
    level.materials.push_back({"wood", 700.0, std::nullopt, 0.5, std::nullopt});
    const std::string expected = R"({
  "$schema": "schema/level.schema.json",
  "format": 1,
  "id": "demo",
  "title": "A \"quoted\" title",
  "sandbox": true,
  "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red", "custom"],
  "custom_bird": {"mass_kg": 0.145, "diameter_m": 0.074, "drag_coefficient": 0.35},
  "blocks": [
    {"material": "stone", "x": 22, "y": 0.25, "w": 3, "h": 0.5},
    {"shape": "circle", "material": "wood", "x": 0.3333333333333333, "y": 0.5, "w": 1},
    {"shape": "hollow_box", "material": "ice", "x": 5, "y": 1, "w": 2, "h": 2, "angle_deg": -15, "wall": 0.2}
  ],
  "pigs": [],
  "environment": {"gravity": 1.62},
  "materials": {"wood": {"density_kg_per_m3": 700, "restitution": 0.5}}
}
)"; // no "stars": the level has the default thresholds, and the writer never adds a field equal to its default
    EXPECT_EQ(writeLevelJson(level, "schema/level.schema.json"), expected);
}

TEST(LevelWriter, LongListsBreakOneItemPerLine)
{
    LevelDef level;
    level.id = "many";
    level.title = "many";
    level.birds.assign(20, "yellow");
    level.pigs = {{"small", 10, 0.25}};
    const std::string text = writeLevelJson(level, "s");
    EXPECT_NE(text.find("  \"birds\": [\n    \"yellow\",\n"), std::string::npos) << text;
    for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
        EXPECT_LE(end - start, 120u) << text.substr(start, end - start);
}

TEST(LevelWriter, SchemaReferenceIsRelativeToWhereTheFileIsSaved)
{
    EXPECT_EQ(schemaReferenceFor(kLevels / "x.json", kSchema), "schema/level.schema.json");
    EXPECT_EQ(schemaReferenceFor(kLevels / "mine" / "x.json", kSchema), "../schema/level.schema.json");
    EXPECT_EQ(schemaReferenceFor("/tmp/a/b/x.json", "/tmp/levels/schema/level.schema.json"),
              "../../levels/schema/level.schema.json");
}

TEST(LevelWriter, SaveWritesTheFileAtomicallyAndItLoads)
{
    test::TempDir dir;
    const LevelDef level = loadLevel((kLevels / "3-4-gusts.json").string(), Catalog::builtin());
    const auto path = dir / "copy.json";
    saveLevel(level, path, kSchema);
    const std::string text = readText(path);
    EXPECT_EQ(text, writeLevelJson(level, schemaReferenceFor(path, kSchema)));
    EXPECT_NE(text.find("\"$schema\": \"" + std::filesystem::relative(kSchema, dir.path()).generic_string() + "\""),
              std::string::npos);
    LevelDef again = loadLevel(path.string(), Catalog::builtin());
    again.sourcePath = level.sourcePath;
    EXPECT_EQ(again, level);
    // No temporary file is left behind.
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path()))
        ++files;
    EXPECT_EQ(files, 1);
}

TEST(LevelWriter, SaveIntoAMissingFolderThrowsAndWritesNothing)
{
    test::TempDir dir;
    const LevelDef level = loadLevel((kLevels / "1-1-first-flight.json").string(), Catalog::builtin());
    EXPECT_THROW(saveLevel(level, dir / "no-such-folder" / "x.json", kSchema), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(dir / "no-such-folder"));
}

} // namespace
} // namespace abalike

#include "save/TempDir.hpp"

#include <abalike/edit/Autosave.hpp>
#include <abalike/edit/Findings.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/world/RestCheck.hpp>
#include <abalike/world/RestFindings.hpp>

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace abalike
{
namespace
{

const std::filesystem::path kSchema =
    std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels" / "schema" / "level.schema.json";

using test::readText;

/// A small level built the way a designer builds one: place, drag, set properties.
void buildLevel(SceneEditor& editor)
{
    editor.place(BlockDef{BlockShape::Box, "stone", 20.0, 0.3, 3.0, 0.5, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 19.0, 1.6, 0.25, 2.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 21.0, 1.6, 0.25, 2.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "ice", 20.0, 2.8, 2.6, 0.25, 0.0, 0.1});
    editor.place(PigDef{"small", 20.0, 0.85});
    editor.place(PigDef{"medium", 26.0, 0.4});
    LevelDef properties = editor.level();
    properties.id = "built-1";
    properties.title = "Built by a test";
    properties.sandbox = false;
    properties.birds = {"red", "yellow", "red"};
    properties.starScores = {5000, 15000, 25000};
    ASSERT_EQ(editor.setProperties(properties, "Level"), "");
}

TEST(SceneSave, ASceneBuiltThroughTheModelSavesAsALevelThatPassesTheChecks)
{
    test::TempDir dir;
    SceneEditor editor(emptyScene());
    buildLevel(editor);
    EXPECT_TRUE(editor.dirty());
    const auto path = dir / "built.json";
    const std::vector<LevelIssue> geometry = editor.save(path, kSchema);
    EXPECT_TRUE(geometry.empty());
    EXPECT_FALSE(editor.dirty());
    EXPECT_EQ(editor.path(), path);
    // The loader's full checks (what `abalike check` runs first), then its rest test.
    LevelDef loaded = loadLevel(path.string(), Catalog::builtin());
    EXPECT_EQ(loaded.blocks, editor.level().blocks);
    EXPECT_EQ(loaded.pigs, editor.level().pigs);
    const RestReport rest = checkRest(loaded);
    EXPECT_TRUE(rest.passed()) << rest.summary();
    // Saving again changes nothing. The schema is in the source tree, not beside the temporary folder: a path
    // there would break when the file is shared, so the new file names none.
    const std::string first = readText(path);
    editor.save(path, kSchema);
    EXPECT_EQ(readText(path), first);
    EXPECT_EQ(first.find("$schema"), std::string::npos) << first;
    EXPECT_EQ(schemaReferenceToWrite(dir / "other.json", "/opt/abalike/share/abalike/schema/level.schema.json"), "");
    EXPECT_EQ(schemaReferenceToWrite(dir / "levels" / "x.json", dir / "schema" / "level.schema.json"),
              "../schema/level.schema.json");
}

TEST(SceneSave, AFilesOwnSchemaReferenceIsKeptAndANewFileNextToTheSchemaGetsAShortOne)
{
    test::TempDir dir;
    std::filesystem::create_directories(dir / "schema");
    std::filesystem::copy_file(kSchema, dir / "schema" / "level.schema.json");
    SceneEditor editor(emptyScene());
    buildLevel(editor);
    editor.save(dir / "new.json", dir / "schema" / "level.schema.json");
    EXPECT_NE(readText(dir / "new.json").find("\"$schema\": \"schema/level.schema.json\""), std::string::npos);
    // A hand-written file pointing at its author's own copy keeps that reference when the editor saves it.
    std::string text = readText(dir / "new.json");
    text.replace(text.find("schema/level.schema.json"), 24, "../mine/level.schema.json");
    std::ofstream(dir / "mine.json") << text;
    editor.save(dir / "mine.json", dir / "schema" / "level.schema.json");
    EXPECT_NE(readText(dir / "mine.json").find("\"$schema\": \"../mine/level.schema.json\""), std::string::npos);
}

TEST(SceneSave, ALevelWithoutPigsIsRefusedAndNothingIsWritten)
{
    test::TempDir dir;
    LevelDef level = emptyScene();
    level.sandbox = false;
    SceneEditor editor(level);
    ASSERT_FALSE(editor.saveProblems().empty());
    EXPECT_NE(editor.saveProblems()[0].message.find("\"sandbox\": true"), std::string::npos);
    try
    {
        editor.save(dir / "x.json", kSchema);
        FAIL() << "saved a level without pigs";
    }
    catch (const LevelLoadError& e)
    {
        EXPECT_EQ(e.issues()[0].file, (dir / "x.json").string());
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "x.json"));
    EXPECT_TRUE(editor.path().empty());
}

TEST(SceneSave, GeometryProblemsAreSavedAndReported)
{
    test::TempDir dir;
    SceneEditor editor(emptyScene());
    editor.snapSettings().surfaces = false;
    editor.place(BlockDef{BlockShape::Box, "wood", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 10.5, 0.5, 1.0, 1.0, 0.0, 0.1});
    const auto issues = editor.save(dir / "overlap.json", kSchema);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer, "/blocks/1");
    const EditableLevel reopened = loadLevelForEditing((dir / "overlap.json").string(), Catalog::builtin());
    EXPECT_EQ(reopened.geometryIssues.size(), 1u);
    EXPECT_THROW(loadLevel((dir / "overlap.json").string(), Catalog::builtin()), LevelLoadError);
}

TEST(SceneSave, FindingsAreMarkedOnTheirObjects)
{
    LevelDef level = emptyScene();
    level.blocks = {{BlockShape::Box, "wood", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1},
                    {BlockShape::Box, "wood", 10.5, 0.5, 1.0, 1.0, 0.0, 0.1},
                    {BlockShape::Box, "ice", 15.0, 3.0, 1.0, 1.0, 0.0, 0.1}};
    level.pigs = {{"small", 600.0, 0.25}};
    const auto geometry = findingsFromIssues(checkLevelGeometry(level, Catalog::builtin()));
    std::vector<ObjectRef> marked;
    for (const Finding& f : geometry)
        if (f.object)
            marked.push_back(*f.object);
    EXPECT_NE(std::find(marked.begin(), marked.end(), ObjectRef{ObjectKind::Block, 0}), marked.end());
    EXPECT_NE(std::find(marked.begin(), marked.end(), ObjectRef{ObjectKind::Block, 1}), marked.end());
    EXPECT_NE(std::find(marked.begin(), marked.end(), ObjectRef{ObjectKind::Pig, 0}), marked.end()) << "out of reach";

    level.blocks.erase(level.blocks.begin() + 1);
    level.pigs = {{"small", 20.0, 0.25}};
    const RestReport report = checkRest(level);
    const auto rest = findingsFromRest(level, Catalog::builtin(), report);
    ASSERT_EQ(rest.size(), 1u) << "only the floating ice block moves";
    EXPECT_EQ(rest[0].object, (ObjectRef{ObjectKind::Block, 1}));
    EXPECT_EQ(rest[0].source, FindingSource::Rest);
    // The editor says what `abalike check` says (the cause, and its verified fix when there is one), not only that
    // it broke.
    const std::vector<LevelIssue> cli = restIssues(level, Catalog::builtin(), report, "");
    ASSERT_EQ(cli.size(), 1u);
    EXPECT_EQ(rest[0].message, cli[0].message);
    EXPECT_EQ(rest[0].message.rfind("falls: nothing is under it", 0), 0u) << rest[0].message;
}

TEST(SceneSave, TheSolverMarksThePigsItCannotReach)
{
    LevelDef level = emptyScene();
    level.sandbox = false;
    level.birds = {"red"};
    // A pig behind a tall stone wall, a second out in the open.
    level.blocks = {{BlockShape::Box, "stone", 12.0, 4.0, 1.0, 8.0, 0.0, 0.1},
                    {BlockShape::Box, "stone", 13.0, 8.5, 3.0, 1.0, 0.0, 0.1}};
    level.pigs = {{"small", 13.0, 0.25}, {"small", 6.0, 0.25}};
    SolverOptions options;
    options.angleSteps = 7;
    options.speedFractions = {0.5, 1.0};
    options.refineRounds = 0;
    options.tryAbilities = false;
    const Solution solution = solveLevel(level, Catalog::builtin(), options);
    ASSERT_FALSE(solution.outcome.won);
    const auto findings = findingsFromSolution(level, solution);
    ASSERT_GE(findings.size(), 2u);
    EXPECT_FALSE(findings[0].object);
    EXPECT_NE(findings[0].message.find("no win found"), std::string::npos);
    EXPECT_EQ(findings[1].object, (ObjectRef{ObjectKind::Pig, 0}));
}

TEST(SceneSave, AutosaveKeepsTheSceneAndItsTarget)
{
    test::TempDir dir;
    SceneEditor editor(emptyScene());
    buildLevel(editor);
    const auto file = autosavePath(dir.path());
    writeAutosave(file, editor.level(), "/somewhere/level.json", Catalog::builtin());
    const auto back = readAutosave(file, Catalog::builtin());
    ASSERT_TRUE(back);
    EXPECT_EQ(back->target, "/somewhere/level.json");
    EXPECT_EQ(back->level.blocks, editor.level().blocks);
    EXPECT_EQ(back->level.id, "built-1");
    removeAutosave(file);
    EXPECT_FALSE(readAutosave(file, Catalog::builtin()));
}

TEST(SceneSave, APiglessLevelIsAutosavedAsASandboxSceneSoItOpensAgain)
{
    test::TempDir dir;
    LevelDef level = emptyScene();
    level.sandbox = false;
    level.blocks = {{BlockShape::Box, "wood", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1}};
    const auto file = autosavePath(dir.path());
    writeAutosave(file, level, "", Catalog::builtin());
    const auto back = readAutosave(file, Catalog::builtin());
    ASSERT_TRUE(back);
    EXPECT_TRUE(back->level.sandbox);
    EXPECT_EQ(back->level.blocks, level.blocks);
}

TEST(SceneSave, ADamagedAutosaveIsReportedNotLoaded)
{
    test::TempDir dir;
    const auto file = autosavePath(dir.path());
    std::ofstream(file) << "{\"format\": 1, \"target\": 3";
    EXPECT_THROW(readAutosave(file, Catalog::builtin()), LevelLoadError);
    std::ofstream(file) << R"({"format": 1, "target": "", "level": {"format": 1}})";
    EXPECT_THROW(readAutosave(file, Catalog::builtin()), LevelLoadError);
}

} // namespace
} // namespace abalike

// `abalike edit` argument handling and the check contract for editor-made files. Every case here fails before a
// window would open, so no display is needed; tests/window/EditorFlowTest.cpp drives the editor itself.
#include "RunAbalike.hpp"

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace abalike::test
{
namespace
{

/// A scratch folder for one test.
class EditCli : public ::testing::Test
{
protected:
    EditCli()
        : m_dir(std::filesystem::temp_directory_path() /
                ("abalike-edit-cli-" + std::to_string(::getpid()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name()))
    {
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    ~EditCli() override
    {
        std::filesystem::remove_all(m_dir);
        if (!m_display.empty())
            ::setenv("DISPLAY", m_display.c_str(), 1);
    }
    void SetUp() override
    {
        // No display for the runs here: a run that gets as far as opening the window stops there with exit 2.
        if (const char* display = std::getenv("DISPLAY"))
            m_display = display;
        ::unsetenv("DISPLAY");
    }

    std::string write(const std::string& name, const std::string& text) const
    {
        std::ofstream(m_dir / name) << text;
        return (m_dir / name).string();
    }
    std::filesystem::path m_dir;
    std::string m_display;
};

RunResult headless(const std::string& args)
{
    return runAbalike("edit " + args);
}

TEST_F(EditCli, AnInvalidLevelExitsTwoWithTheErrorsCheckPrints)
{
    const std::string file = sourcePath("tests/level/malformed/many-problems.json");
    const RunResult editRun = headless(file);
    const RunResult checkRun = runAbalike("check " + file);
    EXPECT_EQ(editRun.exitCode, 2);
    EXPECT_EQ(checkRun.exitCode, 2);
    EXPECT_FALSE(editRun.err.empty());
    EXPECT_EQ(editRun.err, checkRun.err) << "the same lines, FILE:LINE:COL: error: /pointer: message";
    EXPECT_TRUE(editRun.out.empty());
}

TEST_F(EditCli, BrokenJsonAndUnreadableFilesExitTwo)
{
    const RunResult json = headless(write("broken.json", "{\"format\": 1,"));
    EXPECT_EQ(json.exitCode, 2);
    EXPECT_NE(json.err.find("broken.json:1:"), std::string::npos) << json.err;

    const std::string locked = write("locked.json", "{}");
    std::filesystem::permissions(locked, std::filesystem::perms::none);
    const RunResult unreadable = headless(locked);
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
    EXPECT_EQ(unreadable.exitCode, 2);
    if (::geteuid() != 0) // root reads anything
    {
        EXPECT_NE(unreadable.err.find("locked.json"), std::string::npos) << unreadable.err;
    }

    const RunResult folder = headless(m_dir.string());
    EXPECT_EQ(folder.exitCode, 2);
    EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
}

TEST_F(EditCli, ANewFileInAMissingFolderIsAUsageError)
{
    const RunResult r = headless((m_dir / "no-such-folder" / "new.json").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST_F(EditCli, WindowOptionsAreCheckedLikePlays)
{
    for (const std::string bad : {"--frames 0", "--frames -3", "--size 12", "--size 0x0", "--screenshot /no/such/x.png",
                                  "--script /no/such/script.json"})
    {
        const RunResult r = headless(bad);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
        EXPECT_FALSE(r.err.empty()) << bad;
    }
}

TEST_F(EditCli, AValidNewOrGeometricallyFlawedLevelGetsAsFarAsTheWindow)
{
    // Everything before the window was accepted: the run stops only because there is no display.
    for (const std::string& file : {sourcePath("levels/1-1-first-flight.json"), (m_dir / "new.json").string(),
                                    sourcePath("tests/level/malformed/overlapping-blocks.json")})
    {
        const RunResult r = headless(file + " --frames 1");
        EXPECT_EQ(r.exitCode, 2) << file;
        EXPECT_NE(r.err.find("no display"), std::string::npos) << file << ": " << r.err;
    }
    // A level with geometry problems opens: its problems are listed first, as check prints them.
    const RunResult geometry = headless(sourcePath("tests/level/malformed/overlapping-blocks.json") + " --frames 1");
    EXPECT_NE(geometry.err.find("overlapping-blocks.json:"), std::string::npos) << geometry.err;
    EXPECT_NE(geometry.err.find("overlaps /blocks/0"), std::string::npos) << geometry.err;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "new.json")) << "opening a new file does not create it";
}

TEST_F(EditCli, ASceneBuiltThroughTheModelPassesCheck)
{
    SceneEditor editor(emptyScene());
    editor.place(BlockDef{BlockShape::Box, "stone", 18.0, 0.4, 2.0, 0.5, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 17.25, 1.5, 0.25, 1.5, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 18.75, 1.5, 0.25, 1.5, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "ice", 18.0, 2.4, 2.0, 0.25, 0.0, 0.1});
    editor.place(PigDef{"small", 18.0, 0.9});
    LevelDef properties = editor.level();
    properties.sandbox = false;
    properties.id = "model-built";
    properties.title = "Built by the model";
    ASSERT_EQ(editor.setProperties(properties, "Level"), "");
    const auto file = m_dir / "built.json";
    editor.save(file, sourcePath("levels/schema/level.schema.json"));
    const RunResult r = runAbalike("check " + file.string());
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(r.out.rfind("PASS " + file.string() + " (model-built, stands still)", 0), 0u) << r.out;
}

TEST_F(EditCli, CheckReportsASandboxSceneAndACampaignRefusesIt)
{
    SceneEditor editor(emptyScene());
    editor.place(BlockDef{BlockShape::Box, "wood", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    const auto scene = m_dir / "sandbox.json";
    editor.save(scene, sourcePath("levels/schema/level.schema.json"));
    const RunResult check = runAbalike("check " + scene.string() + " --json");
    EXPECT_EQ(check.exitCode, 0) << check.err;
    EXPECT_NE(check.out.find("\"sandbox\": true"), std::string::npos) << check.out;
    const RunResult line = runAbalike("check " + scene.string());
    EXPECT_NE(line.out.find("(sandbox, sandbox scene, stands still)"), std::string::npos) << line.out;

    // A campaign listing it fails, with the error located at the manifest's entry.
    const std::string manifest = write("campaign.json", R"({
  "format": 1,
  "title": "T",
  "episodes": [{"id": "1", "title": "E", "levels": ["sandbox.json"]}]
})");
    const RunResult campaign = runAbalike("check " + manifest);
    EXPECT_EQ(campaign.exitCode, 2);
    EXPECT_NE(campaign.err.find(manifest + ":4:53: error: /episodes/0/levels/0: \"sandbox.json\" is a sandbox scene"),
              std::string::npos)
        << campaign.err;
}

} // namespace
} // namespace abalike::test

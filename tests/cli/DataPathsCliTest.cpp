#include "RunAbalike.hpp"

#include <gtest/gtest.h>
#include <regex>

namespace abalike::test
{
namespace
{

namespace fs = std::filesystem;

class DataPathsCliTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_dir = fs::temp_directory_path() / ("abalike-datapaths-" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "empty");
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path m_dir;
};

TEST(VersionCliTest, PrintsTheVersionAndExitsZero)
{
    const RunResult r = runAbalike("--version");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::regex_match(r.out, std::regex("abalike [0-9]+\\.[0-9]+\\.[0-9]+\n"))) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

// `bench soak` reads the bundled campaign first, so a wrong data folder fails at once and names what it read.
TEST_F(DataPathsCliTest, LevelsDirOverridesTheCampaignFolder)
{
    const fs::path empty = m_dir / "empty";
    const RunResult r = runCommand("ABALIKE_LEVELS_DIR=" + empty.string() + " ABALIKE_SHARE_DIR=/nonexistent " +
                                   ABALIKE_EXECUTABLE + " bench soak --quick --out " + (m_dir / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find((empty / "campaign.json").string()), std::string::npos) << r.err;
}

TEST_F(DataPathsCliTest, ShareDirOverridesTheDataFolder)
{
    const fs::path empty = m_dir / "empty";
    const RunResult r = runCommand("ABALIKE_SHARE_DIR=" + empty.string() + " " + ABALIKE_EXECUTABLE +
                                   " bench soak --quick --out " + (m_dir / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find((empty / "levels" / "campaign.json").string()), std::string::npos) << r.err;
}

TEST_F(DataPathsCliTest, AnExecutableWithoutItsDataSaysWhereItShouldBe)
{
    // A copy of the program in a folder with no data beside it, and no override: it must not fall back to the
    // source tree it was built from.
    const fs::path copy = m_dir / "bin" / "abalike";
    fs::create_directories(copy.parent_path());
    fs::copy_file(ABALIKE_EXECUTABLE, copy);
    const RunResult r = runCommand("env -u ABALIKE_SHARE_DIR -u ABALIKE_LEVELS_DIR " + copy.string() +
                                   " bench soak --quick --out " + (m_dir / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find((m_dir / "share" / "games" / "abalike" / "levels" / "campaign.json").string() +
                         ":0:0: error: /: cannot open file"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find(ABALIKE_SOURCE_DIR), std::string::npos) << r.err;
}

} // namespace
} // namespace abalike::test

#include "RunAbalike.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace abalike::test
{
namespace
{

class ImportCli : public ::testing::Test
{
protected:
    ImportCli()
    {
        m_dir = std::filesystem::temp_directory_path() / ("abalike-import-" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_dir);
    }
    ~ImportCli() override { std::filesystem::remove_all(m_dir); }
    std::filesystem::path write(const std::string& name, const std::string& bytes)
    {
        std::ofstream(m_dir / name, std::ios::binary) << bytes;
        return m_dir / name;
    }
    static std::string read(const std::filesystem::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    std::filesystem::path m_dir;
};

const std::string kTower =
    "<?xml version=\"1.0\" encoding=\"utf-16\"?>\r\n"
    "<Level>\r\n"
    "  <Birds><Bird type=\"BirdRed\"/><Bird type=\"BirdYellow\"/></Birds>\r\n"
    "  <Slingshot x=\"-8\" y=\"-2.5\">\r\n"
    "  <GameObjects>\r\n"
    "    <Block type=\"SquareSmall\" material=\"stone\" x=\"3\" y=\"-3.26\" rotation=\"0\" />\r\n"
    "    <Pig type=\"BasicSmall\" material=\"\" x=\"3\" y=\"-2.82\" rotation=\"0\" />\r\n"
    "  </GameObjects>\r\n"
    "</Level>\r\n";

TEST_F(ImportCli, WritesALevelThatChecksAndReportsEachChangeAtItsLine)
{
    const auto xml = write("Tower 1.xml", kTower);
    const auto json = m_dir / "tower.json";
    const RunResult run = runAbalike("import '" + xml.string() + "' -o " + json.string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("1 block, 1 pig, 0 terrain pieces, 2 birds; 2 warnings"), std::string::npos) << run.out;
    EXPECT_NE(run.err.find("Tower 1.xml:4:3: warning: <Slingshot> is not closed"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("Tower 1.xml:6:5: warning: /blocks/0: was 2.5 cm above the ground; set onto it "
                           "(y = 0.215 in our level)"),
              std::string::npos)
        << run.err;
    const std::string level = read(json);
    EXPECT_NE(level.find("\"id\": \"tower-1\""), std::string::npos) << level;
    EXPECT_NE(level.find("\"birds\": [\"red\", \"yellow\"]"), std::string::npos) << level;
    const RunResult check = runAbalike("check " + json.string());
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

TEST_F(ImportCli, NeverReplacesAFileUnlessToldAndTakesAnIdAndTitle)
{
    const auto xml = write("t.xml", kTower);
    const auto json = write("mine.json", "my own level");
    const RunResult refused = runAbalike("import " + xml.string() + " -o " + json.string());
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("exists (use --force to replace it)"), std::string::npos) << refused.err;
    EXPECT_EQ(read(json), "my own level");
    const RunResult forced =
        runAbalike("import " + xml.string() + " -o " + json.string() + " --force --id sb-tower --title 'SB tower'");
    ASSERT_EQ(forced.exitCode, 0) << forced.err;
    EXPECT_NE(read(json).find("\"id\": \"sb-tower\",\n  \"title\": \"SB tower\""), std::string::npos) << read(json);
}

TEST_F(ImportCli, RefusesABrokenFileWithItsPlaceAndWritesNothing)
{
    const auto xml = write("broken.xml", "<Level>\n<GameObjects>\n  <Block type=\"RectBig\" material=\"wood\" "
                                         "x=\"two\" y=\"-3\"/>\n</GameObjects>\n</Level>\n");
    const auto json = m_dir / "broken.json";
    const RunResult run = runAbalike("import " + xml.string() + " -o " + json.string());
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("broken.xml:3:3: error: <Block> x=\"two\" is not a number (expected e.g. x=\"1.5\")"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(std::filesystem::exists(json));
}

} // namespace
} // namespace abalike::test

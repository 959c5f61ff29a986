// `abalike chart table` (a shot export drawn as a spreadsheet shows it) and `simulate --csv` / `--wording` together.
#include "RunAbalike.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace abalike::test
{
namespace
{

std::filesystem::path tempFile(const std::string& name)
{
    return std::filesystem::temp_directory_path() / ("abalike-table-" + std::to_string(::getpid()) + "-" + name);
}

TEST(ChartTableCli, AShotExportBecomesASpreadsheetPicture)
{
    const auto csv = tempFile("shots.csv");
    const auto png = tempFile("shots.png");
    const RunResult simulate = runAbalike("simulate " + sourcePath("levels/lessons/lesson-predict.json") +
                                          " --shot 35,16 --csv " + csv.string());
    ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
    const RunResult table =
        runAbalike("chart table " + csv.string() + " --out " + png.string() + " --rows 12 --every 5");
    ASSERT_EQ(table.exitCode, 0) << table.err;
    EXPECT_NE(table.out.find("(12 of "), std::string::npos) << table.out;
    std::ifstream in(png, std::ios::binary);
    char signature[8] = {};
    in.read(signature, 8);
    EXPECT_EQ(std::string(signature + 1, 3), "PNG");
    EXPECT_GT(std::filesystem::file_size(png), 5000u);
    std::filesystem::remove(csv);
    std::filesystem::remove(png);
}

TEST(ChartTableCli, ARaggedRowIsAnErrorAtItsLine)
{
    const auto csv = tempFile("ragged.csv");
    std::ofstream(csv) << "a,b,c\n1,2,3\n4,5\n";
    const RunResult table = runAbalike("chart table " + csv.string() + " --out " + tempFile("r.png").string());
    EXPECT_EQ(table.exitCode, 2);
    EXPECT_NE(table.err.find("ragged.csv:3: expected 3 cells like the header, got 2"), std::string::npos) << table.err;
    const RunResult missing = runAbalike("chart table /nonexistent/x.csv --out " + tempFile("m.png").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("/nonexistent/x.csv: cannot read the file"), std::string::npos) << missing.err;
    std::filesystem::remove(csv);
}

TEST(SimulateWording, UniversityNamesTheMethodAndSchoolDoesNot)
{
    const std::string args = "simulate " + sourcePath("levels/lessons/lesson-predict.json") + " --shot 35,16";
    const RunResult school = runAbalike(args);
    const RunResult university = runAbalike(args + " --wording university");
    ASSERT_EQ(school.exitCode, 0) << school.err;
    ASSERT_EQ(university.exitCode, 0) << university.err;
    EXPECT_EQ(school.out.find("RK4"), std::string::npos) << school.out;
    EXPECT_NE(university.out.find("Method: the preview and the world integrate the flight with the same RK4 steps"),
              std::string::npos)
        << university.out;
    const RunResult wrong = runAbalike(args + " --wording expert");
    EXPECT_EQ(wrong.exitCode, 2);
    EXPECT_NE(wrong.err.find("--wording: expected school or university, got \"expert\""), std::string::npos);
}

} // namespace
} // namespace abalike::test

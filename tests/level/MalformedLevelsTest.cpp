#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace abalike
{
namespace
{

/// tests/level/malformed/NAME.json holds a broken level; NAME.expected the lines (or stable beginnings of lines)
/// the loader must report for it, with the file named NAME.json.
const std::filesystem::path kFolder = std::filesystem::path(ABALIKE_SOURCE_DIR) / "tests/level/malformed";

std::vector<std::string> malformedNames()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kFolder))
        if (entry.path().extension() == ".json")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty())
            out.push_back(line);
    return out;
}

/// Every problem the loader reports for text, one formatted line each; empty if it loads.
std::string loadErrors(const std::string& text, const std::string& fileName)
{
    try
    {
        parseLevel(text, fileName, Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        std::string all;
        for (const LevelIssue& issue : e.issues())
            all += issue.format() + "\n";
        return all;
    }
    return "";
}

class MalformedLevel : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MalformedLevel, ReportsTheExpectedErrors)
{
    const std::string name = GetParam();
    const auto expected = lines(readFile(kFolder / (name + ".expected")));
    ASSERT_FALSE(expected.empty()) << name << ".expected is missing or empty";
    const std::string errors = loadErrors(readFile(kFolder / (name + ".json")), name + ".json");
    ASSERT_FALSE(errors.empty()) << name << ".json loaded without error";
    for (const std::string& line : expected)
        EXPECT_NE(errors.find(line), std::string::npos) << "expected: " << line << "\ngot:\n" << errors;
    for (const std::string& line : lines(errors))
        EXPECT_EQ(line.rfind(name + ".json:", 0), 0u) << "not in FILE:LINE:COL form: " << line;
}

INSTANTIATE_TEST_SUITE_P(Suite, MalformedLevel, ::testing::ValuesIn(malformedNames()),
                         [](const ::testing::TestParamInfo<std::string>& info)
                         {
                             std::string name = info.param;
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

TEST(MalformedLevels, SuiteHasAtLeastFortyFiles)
{
    EXPECT_GE(malformedNames().size(), 40u);
}

/// Hostile inputs too big to commit are made here. Each must fail fast with one clear error.
class GeneratedInput : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_path = std::filesystem::temp_directory_path() /
                 ("abalike-malformed-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
    }
    void TearDown() override { std::filesystem::remove(m_path); }

    /// Loads the file at m_path and returns the first error line, checking it took less than a second.
    std::string firstError()
    {
        const auto start = std::chrono::steady_clock::now();
        std::string first;
        try
        {
            loadLevel(m_path.string(), Catalog::builtin());
        }
        catch (const LevelLoadError& e)
        {
            first = e.issues().at(0).format();
        }
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
        return first;
    }

    std::filesystem::path m_path;
};

TEST_F(GeneratedInput, FiftyMegabyteFile)
{
    {
        std::ofstream out(m_path, std::ios::binary);
        out << R"({"format": 1, "id": "big", "title": ")";
        const std::string chunk(1 << 20, 'a');
        for (int i = 0; i < 50; ++i)
            out << chunk;
        out << "\"}";
    }
    const std::string error = firstError();
    EXPECT_NE(
        error.find(":1:1: error: /: file too large (expected a level of at most 4194304 bytes, got 52428839 bytes)"),
        std::string::npos)
        << error;
}

TEST_F(GeneratedInput, HundredThousandDeepArrays)
{
    std::ofstream(m_path, std::ios::binary) << std::string(100000, '[') << std::string(100000, ']');
    const std::string error = firstError();
    EXPECT_NE(error.find(":1:65: error: /: JSON nested too deeply (expected at most 64 levels"), std::string::npos)
        << error;
}

TEST_F(GeneratedInput, HundredThousandDeepObjects)
{
    std::string text;
    for (int i = 0; i < 100000; ++i)
        text += "{\"a\":";
    text += "1" + std::string(100000, '}');
    std::ofstream(m_path, std::ios::binary) << text;
    EXPECT_NE(firstError().find("JSON nested too deeply"), std::string::npos);
}

TEST_F(GeneratedInput, RandomBytes)
{
    std::string bytes;
    std::uint32_t state = 12345;
    for (int i = 0; i < 100000; ++i)
    {
        state = state * 1664525u + 1013904223u;
        bytes += static_cast<char>(state >> 24);
    }
    std::ofstream(m_path, std::ios::binary) << bytes;
    EXPECT_NE(firstError().find("error: /:"), std::string::npos);
}

TEST_F(GeneratedInput, MissingFile)
{
    EXPECT_NE(firstError().find("cannot open file"), std::string::npos);
}

} // namespace
} // namespace abalike

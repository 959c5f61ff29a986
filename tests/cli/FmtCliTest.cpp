#include "RunAbalike.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace abalike::test
{
namespace
{

std::string readAll(const std::filesystem::path& path)
{
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FmtCli : public ::testing::Test
{
protected:
    std::filesystem::path file(const std::string& name, const std::string& text)
    {
        const auto path =
            std::filesystem::temp_directory_path() / ("abalike-fmt-" + std::to_string(::getpid()) + "-" + name);
        std::ofstream(path) << text;
        m_paths.push_back(path);
        return path;
    }
    ~FmtCli() override
    {
        for (const auto& path : m_paths)
            std::filesystem::remove(path);
    }
    std::vector<std::filesystem::path> m_paths;
};

TEST_F(FmtCli, RewritesAHandWrittenLevelInTheEditorsLayoutAndKeepsItsSchemaReference)
{
    const auto path = file("hand.json", R"({"$schema": "../my/schema.json", "format": 1, "id": "hand", "title": "Hand",
      "slingshot": {"x": 0.0, "y": 1.5, "max_force_n": 1800},
      "birds": ["red"],
      "blocks": [ { "material": "wood",  "x": 22.0, "y": 1.0, "w": 0.25, "h": 2.0 } ],
      "terrain": [ { "points": [[14.0, 0], [18, 0], [16, 2.50]] } ],
      "pigs": [ { "type": "small", "x": 30.0, "y": 0.25 } ], "stars": [10000, 20000, 30000]})");
    const RunResult check = runAbalike("fmt --check " + path.string());
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_NE(check.out.find("would reformat"), std::string::npos);
    const RunResult fmt = runAbalike("fmt " + path.string());
    EXPECT_EQ(fmt.exitCode, 0) << fmt.err;
    EXPECT_EQ(readAll(path), R"({
  "$schema": "../my/schema.json",
  "format": 1,
  "id": "hand",
  "title": "Hand",
  "slingshot": {"x": 0, "y": 1.5, "max_force_n": 1800},
  "birds": ["red"],
  "blocks": [
    {"material": "wood", "x": 22, "y": 1, "w": 0.25, "h": 2}
  ],
  "pigs": [
    {"type": "small", "x": 30, "y": 0.25}
  ],
  "terrain": [
    {"points": [[14, 0], [18, 0], [16, 2.5]]}
  ]
}
)");
    // Formatted once, it stays.
    EXPECT_EQ(runAbalike("fmt --check " + path.string()).exitCode, 0);
}

TEST_F(FmtCli, ABrokenFileIsLeftAloneWithItsErrors)
{
    const std::string text = R"({"format": 1, "id": "x", "title": "X", "slingshot": {"x": 0, "y": 1.5},
      "birds": ["bleu"], "pigs": [{"type": "small", "x": 30, "y": 0.25}]})";
    const auto path = file("broken.json", text);
    const RunResult r = runAbalike("fmt " + path.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(":2:17: error: /birds/0: unknown bird \"bleu\""), std::string::npos) << r.err;
    EXPECT_EQ(readAll(path), text);
}

} // namespace
} // namespace abalike::test

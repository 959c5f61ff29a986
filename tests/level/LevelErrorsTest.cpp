#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// Parses text expected to fail and returns every formatted problem, one per line.
std::string loaderErrorsOf(const std::string& text)
{
    try
    {
        parseLevel(text, "level.json", Catalog::builtin());
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

const char* const kValid = R"({
  "format": 1, "id": "t", "title": "T",
  "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red"],
  "pigs": [{"type": "small", "x": 10, "y": 0.25}]
})";

TEST(LevelErrors, ValidMinimalLevelLoads)
{
    EXPECT_EQ(loaderErrorsOf(kValid), "");
}

TEST(LevelErrors, SyntaxErrorGivesLineAndColumn)
{
    const std::string errors = loaderErrorsOf("{\n  \"format\": 1,\n  \"id\": \"t\"\n  \"title\": \"T\"\n}");
    EXPECT_NE(errors.find("level.json:4:3: error: /: invalid JSON"), std::string::npos) << errors;
}

TEST(LevelErrors, EmptyFile)
{
    EXPECT_NE(loaderErrorsOf("  \n").find("empty file"), std::string::npos);
}

TEST(LevelErrors, DeepNestingIsRejectedWithoutParsing)
{
    EXPECT_NE(loaderErrorsOf(std::string(100000, '[') + std::string(100000, ']')).find("nested too deeply"),
              std::string::npos);
}

TEST(LevelErrors, HugeNumberIsAnError)
{
    std::string text = kValid;
    text.replace(text.find("\"x\": 10"), 7, "\"x\": 1e400");
    EXPECT_NE(loaderErrorsOf(text).find("error"), std::string::npos);
}

TEST(LevelErrors, ReportsEveryProblemWithPointerAndSuggestion)
{
    const std::string errors = loaderErrorsOf(R"({
  "format": 1, "id": "t", "title": "T",
  "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red", "bleu"],
  "blocks": [{"material": "stone", "x": 5, "y": 0.5, "w": 1, "h": 40}],
  "pigs": [{"type": "small", "x": "ten", "y": 0.25}],
  "enviroment": {}
})");
    EXPECT_NE(errors.find("level.json:4:20: error: /birds/1: unknown bird \"bleu\" (did you mean \"blue\"?)"),
              std::string::npos)
        << errors;
    EXPECT_NE(
        errors.find(
            "/blocks/0/h: outside the sizes Box2D simulates well for a moving body (expected 0.1 to 10 m, got 40)"),
        std::string::npos)
        << errors;
    EXPECT_NE(errors.find("/pigs/0/x: expected a number, got the string \"ten\""), std::string::npos) << errors;
    EXPECT_NE(errors.find("/enviroment: unknown key \"enviroment\" (did you mean \"environment\"?)"), std::string::npos)
        << errors;
}

} // namespace
} // namespace abalike

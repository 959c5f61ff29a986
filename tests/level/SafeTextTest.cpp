#include "save/TempDir.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/world/Catalog.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace abalike
{
namespace
{

/// The rule as the issue states it, written independently of SafeText.cpp.
bool inTheRule(char32_t c)
{
    return c <= 0x1F || (c >= 0x7F && c <= 0x9F) || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

std::string utf8(char32_t c)
{
    std::string out;
    const auto push = [&](unsigned value)
    {
        out.push_back(static_cast<char>(value));
    };
    if (c < 0x80)
        push(c);
    else if (c < 0x800)
        push(0xC0 | (c >> 6)), push(0x80 | (c & 0x3F));
    else if (c < 0x10000)
        push(0xE0 | (c >> 12)), push(0x80 | ((c >> 6) & 0x3F)), push(0x80 | (c & 0x3F));
    else
        push(0xF0 | (c >> 18)), push(0x80 | ((c >> 12) & 0x3F)), push(0x80 | ((c >> 6) & 0x3F)),
            push(0x80 | (c & 0x3F));
    return out;
}

/// "\u001B" for a code point inside a JSON string (surrogate pairs beyond U+FFFF).
std::string jsonEscape(char32_t c)
{
    char buffer[16];
    if (c < 0x10000)
        std::snprintf(buffer, sizeof buffer, "\\u%04X", static_cast<unsigned>(c));
    else
        std::snprintf(buffer, sizeof buffer, "\\u%04X\\u%04X", static_cast<unsigned>(0xD800 + ((c - 0x10000) >> 10)),
                      static_cast<unsigned>(0xDC00 + ((c - 0x10000) & 0x3FF)));
    return buffer;
}

std::vector<LevelIssue> issuesOf(const std::string& text)
{
    try
    {
        parseLevel(text, "level.json", Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        return e.issues();
    }
    return {};
}

/// A valid level with `inject` placed as title, hint, key or nested key.
std::string levelWith(const std::string& title, const std::string& hint, const std::string& key)
{
    return R"({"format": 1, "id": "t", "title": ")" + title + R"(", "hints": [")" + hint + R"("],)" +
           (key.empty() ? "" : "\"" + key + "\": 1, ") +
           R"("slingshot": {"x": 0, "y": 1.5}, "birds": ["red"], "pigs": [{"type": "small", "x": 10, "y": 0.25}]})";
}

TEST(SafeText, EveryCodePointIsClassifiedAsTheRuleSays)
{
    int unsafe = 0;
    for (char32_t c = 0; c <= 0x10FFFF; ++c)
    {
        if (c >= 0xD800 && c <= 0xDFFF)
            continue;
        ASSERT_EQ(isUnsafeCharacter(c), inTheRule(c)) << std::hex << static_cast<unsigned>(c);
        const std::string text = std::string("ab").append(utf8(c)).append("z");
        const auto found = findUnsafeCharacter(text);
        ASSERT_EQ(found.has_value(), inTheRule(c)) << std::hex << static_cast<unsigned>(c);
        if (found)
        {
            EXPECT_EQ(found->index, 2u);
            EXPECT_EQ(found->codePoint, c);
            ++unsafe;
        }
        // Escaping leaves safe characters alone and removes every unsafe one.
        const std::string escaped = escapeForTerminal(text);
        ASSERT_EQ(escaped == text, !inTheRule(c)) << std::hex << static_cast<unsigned>(c);
        ASSERT_FALSE(findUnsafeCharacter(escaped)) << escaped;
    }
    EXPECT_EQ(unsafe, 32 + 33 + 5 + 4);
}

TEST(SafeText, EscapesShowTheBytesOrTheCodePoint)
{
    EXPECT_EQ(escapeForTerminal("\x1b[31mred\x1b[0m"), "\\x1B[31mred\\x1B[0m");
    EXPECT_EQ(escapeForTerminal("a\tb\nc\x7f"), "a\\x09b\\x0Ac\\x7F");
    EXPECT_EQ(escapeForTerminal("\xc2\x9b"
                                "31m"),
              "\\u{009B}31m");
    EXPECT_EQ(escapeForTerminal("file\xe2\x80\xaegnp.json"), "file\\u{202E}gnp.json");
    EXPECT_EQ(escapeForTerminal("bad \xff\xfe utf-8 \xe2\x82"), "bad \\xFF\\xFE utf-8 \\xE2\\x82");
    // Ordinary names, paths with backslashes and other scripts are unchanged, and escaping twice changes nothing.
    for (const std::string ordinary :
         {"levels/1-1-first-flight.json", "C:\\levels\\x1B.json", "Mond · 月 · 🐦 · ‏"})
        EXPECT_EQ(escapeForTerminal(ordinary), ordinary);
    const std::string once = escapeForTerminal("\x1b]0;title\x07");
    EXPECT_EQ(escapeForTerminal(once), once);
}

TEST(SafeText, DescribesCharactersByName)
{
    EXPECT_EQ(describeCharacter(0x1B), "U+001B (escape)");
    EXPECT_EQ(describeCharacter(0x0A), "U+000A (newline)");
    EXPECT_EQ(describeCharacter(0x202E), "U+202E (right-to-left override)");
    EXPECT_EQ(describeCharacter(0x85), "U+0085 (C1 control)");
    EXPECT_EQ(describeCharacter(0xE9), "U+00E9");
}

// The loader rejects every unsafe character wherever a string or key is, and the error names the place; the schema
// test (tools/validate_levels.py) checks the schema against the same characters.
TEST(SafeText, TheLoaderRejectsEveryUnsafeCharacterInStringsAndKeys)
{
    for (char32_t c = 0; c <= 0x2069; ++c)
    {
        if (!inTheRule(c))
            continue;
        const std::string bad = std::string("x").append(jsonEscape(c)).append("y");
        const auto title = issuesOf(levelWith(bad, "ok", ""));
        ASSERT_EQ(title.size(), 1u) << std::hex << static_cast<unsigned>(c);
        EXPECT_EQ(title[0].pointer, "/title");
        EXPECT_EQ(title[0].line, 1);
        EXPECT_NE(title[0].message.find(describeCharacter(c) + " at character 2"), std::string::npos)
            << title[0].message;
        const auto hint = issuesOf(levelWith("T", bad, ""));
        ASSERT_EQ(hint.size(), 1u);
        EXPECT_EQ(hint[0].pointer, "/hints/0");
        const auto key = issuesOf(levelWith("T", "ok", bad));
        ASSERT_EQ(key.size(), 1u) << "a bad key is reported once, not also as unknown";
        EXPECT_NE(key[0].message.find("unsafe character in a key"), std::string::npos);
        // The key's position, not the document's: column of its first character inside the quotes.
        const std::string text = levelWith("T", "ok", bad);
        EXPECT_EQ(key[0].column, static_cast<int>(text.find("\"x\\u") + 2));
    }
}

TEST(SafeText, TheLoaderAcceptsOrdinaryText)
{
    for (const char32_t c : {0x20u, 0x7Eu, 0xA0u, 0xE9u, 0xB5u, 0x200Eu, 0x200Fu, 0x2028u, 0x2029u, 0x2065u, 0x206Au,
                             0xFEFFu, 0xFFFDu, 0x1F426u})
        EXPECT_TRUE(issuesOf(levelWith(std::string("x").append(jsonEscape(c)).append("y"),
                                       std::string("hint ").append(utf8(c)), ""))
                        .empty())
            << std::hex << static_cast<unsigned>(c);
}

TEST(SafeText, NestedStringsAndFieldsAddedLaterAreCoveredToo)
{
    // An unknown nested key with a control character: reported as unsafe at its own place.
    const std::string text = R"({"format": 1, "id": "t", "title": "T", "slingshot": {"x": 0, "y": 1.5, "n\u0007te": 2},
      "birds": ["red"], "pigs": [{"type": "small\u202e", "x": 10, "y": 0.25}]})";
    const auto issues = issuesOf(text);
    ASSERT_GE(issues.size(), 2u);
    EXPECT_EQ(issues[0].pointer, "/slingshot/n\ate");
    const int column = static_cast<int>(text.find("n\\u0007") + 1);
    EXPECT_EQ(issues[0].column, column);
    EXPECT_EQ(issues[0].format(),
              "level.json:1:" + std::to_string(column) +
                  ": error: /slingshot/n\\x07te: unsafe character in a key (expected "
                  "text without control or bidirectional characters, got U+0007 (bell) at character 2)");
    EXPECT_EQ(issues[1].pointer, "/pigs/0/type");
}

TEST(SafeText, TheCampaignManifestIsCheckedToo)
{
    const test::TempDir dir;
    const auto write = [&](const std::string& episodeTitle, const std::string& level)
    {
        std::ofstream(dir / "campaign.json") << R"({"format": 1, "episodes": [{"id": "1", "title": ")" + episodeTitle +
                                                    R"(", "levels": [")" + level + R"("]}]})";
        return (dir / "campaign.json").string();
    };
    std::ofstream(dir / "a.json") << "{}"; // listed files must exist; what is in them is the level loader's business
    EXPECT_NO_THROW(loadCampaignEpisodes(write("Launch angle", "a.json")));
    for (const auto& [title, level, pointer] : {std::tuple{"Launch\\u001b[2J", "a.json", "/episodes/0/title"},
                                                {"ok", "a\\u202e.json", "/episodes/0/levels/0"},
                                                {"ok", "a\\n.json", "/episodes/0/levels/0"}})
    {
        try
        {
            loadCampaignEpisodes(write(title, level));
            ADD_FAILURE() << "accepted " << title << " " << level;
        }
        catch (const LevelLoadError& e)
        {
            // The unsafe name is reported (and, for a level name, that no such file exists).
            ASSERT_GE(e.issues().size(), 1u);
            EXPECT_EQ(e.issues()[0].pointer, pointer);
            EXPECT_NE(e.issues()[0].message.find("unsafe character in a string"), std::string::npos);
        }
    }
}

TEST(SafeText, FileNamesAreEscapedAndOrdinaryOnesKeepTheirForm)
{
    const LevelIssue ordinary{"levels/1-1-first-flight.json", 4, 12, "/title", "expected a non-empty string"};
    EXPECT_EQ(ordinary.format(), "levels/1-1-first-flight.json:4:12: error: /title: expected a non-empty string");
    const LevelIssue hostile{"evil\x1b]0;owned\x07.json", 0, 0, "", "cannot open file"};
    EXPECT_EQ(hostile.format(), "evil\\x1B]0;owned\\x07.json:0:0: error: /: cannot open file");
}

} // namespace
} // namespace abalike

#include "RunAbalike.hpp"

#include <gtest/gtest.h>

namespace abalike::test
{
namespace
{

bool hasRawControl(const std::string& text)
{
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n')
            return true;
    return false;
}

// Names that come from the command line or from files reach the terminal escaped; nothing raw gets through.
TEST(TerminalTextCliTest, AHostileFileNameIsEscaped)
{
    const RunResult r = runAbalike("check \"$(printf 'evil\\033[31m\\033]0;owned\\007.json')\"");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(hasRawControl(r.out + r.err)) << r.out << r.err;
    EXPECT_NE(r.out.find("FAIL evil\\x1B[31m\\x1B]0;owned\\x07.json"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("evil\\x1B[31m\\x1B]0;owned\\x07.json:0:0: error: /: cannot open file"), std::string::npos)
        << r.err;
}

TEST(TerminalTextCliTest, AnUnknownCommandIsEscaped)
{
    const RunResult r = runAbalike("\"$(printf 'fly\\033[2J')\"");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown command \"fly\\x1B[2J\""), std::string::npos) << r.err;
    EXPECT_FALSE(hasRawControl(r.err)) << r.err;
}

TEST(TerminalTextCliTest, ALevelWithAnEscapeSequenceIsRejectedWithItsPlace)
{
    const RunResult r = runAbalike("check " + sourcePath("tests/level/malformed/title-escape-sequence.json"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(hasRawControl(r.out + r.err)) << r.out << r.err;
    EXPECT_NE(r.err.find("title-escape-sequence.json:4:12: error: /title: unsafe character in a string"),
              std::string::npos)
        << r.err;
}

TEST(TerminalTextCliTest, OrdinaryOutputIsUnchanged)
{
    const RunResult r = runAbalike("check " + sourcePath("tests/level/malformed/empty-title.json"));
    EXPECT_EQ(r.err, sourcePath("tests/level/malformed/empty-title.json") +
                         ":4:12: error: /title: expected a non-empty string, got \"\"\n");
}

} // namespace
} // namespace abalike::test

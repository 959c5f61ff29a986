#include "FileSizeLimit.hpp"
#include "TempDir.hpp"

#include <abalike/save/AtomicWrite.hpp>
#include <abalike/save/SaveError.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using test::entries;
using test::readText;
using test::TempDir;
using test::writeText;

TEST(AtomicWrite, CreatesAndReplacesLeavingNoTemporaryFiles)
{
    const TempDir dir;
    writeFileAtomically(dir / "a.json", "first");
    EXPECT_EQ(readText(dir / "a.json"), "first");
    writeFileAtomically(dir / "a.json", "second, longer");
    EXPECT_EQ(readText(dir / "a.json"), "second, longer");
    writeFileAtomically(dir / "a.json", "");
    EXPECT_EQ(readText(dir / "a.json"), "");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.json"});
}

TEST(AtomicWrite, MissingFolderIsAnErrorNamingTheFile)
{
    const TempDir dir;
    try
    {
        writeFileAtomically(dir / "missing" / "a.json", "x");
        FAIL() << "expected SaveIoError";
    }
    catch (const SaveIoError& e)
    {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write " + (dir / "missing" / "a.json").string() + ": No such file or directory");
    }
}

TEST(AtomicWrite, AFullDiskKeepsTheOldFileWhole)
{
    const TempDir dir;
    writeText(dir / "a.json", "old progress");
    {
        const test::FileSizeLimit full(16);
        EXPECT_THROW(writeFileAtomically(dir / "a.json", std::string(100000, 'n')), SaveIoError);
    }
    EXPECT_EQ(readText(dir / "a.json"), "old progress");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.json"}) << "the temporary file is removed";
}

TEST(AtomicWrite, ADirectoryInTheWayIsAnError)
{
    const TempDir dir;
    std::filesystem::create_directories(dir / "a.json" / "inside");
    EXPECT_THROW(writeFileAtomically(dir / "a.json", "x"), SaveIoError);
    EXPECT_TRUE(std::filesystem::is_directory(dir / "a.json" / "inside"));
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.json"});
}

} // namespace
} // namespace abalike

#include <abalike/save/DataDirectory.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(DataDirectory, AbalikeDataDirComesFirst)
{
    EXPECT_EQ(dataDirectoryFrom("/srv/abalike", "/home/p/.data", "/home/p"), "/srv/abalike");
}

TEST(DataDirectory, ThenXdgDataHome)
{
    EXPECT_EQ(dataDirectoryFrom(nullptr, "/home/p/.data", "/home/p"), "/home/p/.data/abalike");
    EXPECT_EQ(dataDirectoryFrom("", "/home/p/.data", "/home/p"), "/home/p/.data/abalike");
}

TEST(DataDirectory, ThenHome)
{
    EXPECT_EQ(dataDirectoryFrom(nullptr, nullptr, "/home/p"), "/home/p/.local/share/abalike");
    EXPECT_EQ(dataDirectoryFrom(nullptr, "", "/home/p"), "/home/p/.local/share/abalike");
    EXPECT_EQ(dataDirectoryFrom(nullptr, "relative/data", "/home/p"), "/home/p/.local/share/abalike")
        << "the XDG spec says to ignore a relative XDG_DATA_HOME";
}

TEST(DataDirectory, NothingKnownGivesEmpty)
{
    EXPECT_TRUE(dataDirectoryFrom(nullptr, nullptr, nullptr).empty());
    EXPECT_TRUE(dataDirectoryFrom("", "", "").empty());
}

TEST(CacheDirectory, BesideTheDataWhenAbalikeDataDirIsSetElseXdgCacheHomeElseHome)
{
    EXPECT_EQ(cacheDirectoryFrom("/srv/abalike", "/home/p/.c", "/home/p"), "/srv/abalike/cache");
    EXPECT_EQ(cacheDirectoryFrom(nullptr, "/home/p/.c", "/home/p"), "/home/p/.c/abalike");
    EXPECT_EQ(cacheDirectoryFrom(nullptr, "relative/c", "/home/p"), "/home/p/.cache/abalike");
    EXPECT_EQ(cacheDirectoryFrom("", "", "/home/p"), "/home/p/.cache/abalike");
    EXPECT_TRUE(cacheDirectoryFrom(nullptr, nullptr, nullptr).empty());
}

} // namespace
} // namespace abalike

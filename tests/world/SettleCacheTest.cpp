#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/SettleCache.hpp>
#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace abalike
{
namespace
{

/// Every body's position, angle and velocity, as raw bits.
std::vector<float> snapshot(const GameWorld& world)
{
    std::vector<float> values;
    for (const b2Body* body = world.box2d().GetBodyList(); body != nullptr; body = body->GetNext())
    {
        values.insert(values.end(),
                      {body->GetPosition().x, body->GetPosition().y, body->GetAngle(), body->GetLinearVelocity().x,
                       body->GetLinearVelocity().y, body->GetAngularVelocity()});
    }
    return values;
}

struct Played
{
    bool reused = false;
    std::vector<float> afterSettle;
    std::vector<float> afterShot;
    int pigsLeft = 0;
};

/// Settles the level, then fires the shot and plays 4 s of it.
Played play(const LevelDef& level, double angleDeg, double speedMps)
{
    GameSession session(level);
    session.step();
    Played p;
    p.reused = session.world().settleReused();
    p.afterSettle = snapshot(session.world());
    session.launch(angleDeg, speedMps);
    for (int i = 0; i < 240; ++i)
        session.step();
    p.afterShot = snapshot(session.world());
    p.pigsLeft = session.pigsRemaining();
    return p;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

LevelDef castle()
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/6-5-citadel.json", Catalog::builtin());
}

class SettleCacheTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        SettleCache::shared().clear();
        m_dir = std::filesystem::temp_directory_path() / ("abalike-settle-test-" + std::to_string(::getpid()));
        std::filesystem::remove_all(m_dir);
    }
    void TearDown() override
    {
        SettleCache::shared().setDirectory("", "");
        SettleCache::shared().clear();
        std::filesystem::remove_all(m_dir);
    }
    std::filesystem::path m_dir;
};

TEST_F(SettleCacheTest, ASecondWorldStartsFromTheStoredStateAndPlaysTheSameToTheBit)
{
    const LevelDef level = castle();
    const Played first = play(level, 36.0, 21.0);
    const Played second = play(level, 36.0, 21.0);
    EXPECT_FALSE(first.reused);
    EXPECT_TRUE(second.reused);
    EXPECT_EQ(SettleCache::shared().size(), 1u);
    EXPECT_TRUE(sameBits(first.afterSettle, second.afterSettle));
    EXPECT_TRUE(sameBits(first.afterShot, second.afterShot));
    EXPECT_EQ(first.pigsLeft, second.pigsLeft);
    EXPECT_LT(first.pigsLeft, static_cast<int>(level.pigs.size())) << "the shot should break into the castle";
}

TEST_F(SettleCacheTest, AnotherLevelOrSettingMisses)
{
    LevelDef level = castle();
    play(level, 30.0, 21.0);
    level.blocks[0].x += 0.001;
    EXPECT_FALSE(play(level, 30.0, 21.0).reused);
    WorldSettings settings;
    settings.velocityIterations = 9;
    GameSession other(castle(), Catalog::builtin(), settings);
    other.step();
    EXPECT_FALSE(other.world().settleReused());
    EXPECT_EQ(SettleCache::shared().size(), 3u);
}

TEST_F(SettleCacheTest, FilesCarryItToTheNextRunAndAForeignOrDamagedFileIsSolvedAgain)
{
    const LevelDef level = castle();
    SettleCache::shared().setDirectory(m_dir.string(), "build 1");
    const Played computed = play(level, 30.0, 21.0);
    ASSERT_EQ(std::distance(std::filesystem::directory_iterator(m_dir), {}), 1);
    const std::filesystem::path file = std::filesystem::directory_iterator(m_dir)->path();

    SettleCache::shared().clear(); // a new run of the same build
    const Played fromFile = play(level, 30.0, 21.0);
    EXPECT_TRUE(fromFile.reused);
    EXPECT_TRUE(sameBits(computed.afterShot, fromFile.afterShot));

    SettleCache::shared().clear();
    SettleCache::shared().setDirectory(m_dir.string(), "build 2"); // another build: its physics may differ
    EXPECT_FALSE(play(level, 30.0, 21.0).reused);

    const auto size = std::filesystem::file_size(file);
    for (const auto offset : {size / 2, size - 3, std::uintmax_t{5}})
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(static_cast<std::streamoff>(offset));
        const char c = static_cast<char>(f.get());
        f.seekp(static_cast<std::streamoff>(offset));
        f.put(static_cast<char>(c ^ 0x40));
        f.close();
        SettleCache::shared().clear();
        const Played damaged = play(level, 30.0, 21.0);
        EXPECT_FALSE(damaged.reused) << "byte " << offset;
        EXPECT_TRUE(sameBits(computed.afterShot, damaged.afterShot)) << "byte " << offset;
    }
    std::filesystem::resize_file(file, size / 3);
    SettleCache::shared().clear();
    EXPECT_FALSE(play(level, 30.0, 21.0).reused);
}

TEST_F(SettleCacheTest, TurnedOffOrWithABirdAlreadyFlyingTheSettleStepIsSolvedInPlace)
{
    WorldSettings off;
    off.settleCache = false;
    for (int run = 0; run < 2; ++run)
    {
        GameSession session(castle(), Catalog::builtin(), off);
        session.step();
        EXPECT_FALSE(session.world().settleReused());
    }
    for (int run = 0; run < 2; ++run)
    {
        GameSession session(castle());
        session.launch(30.0, 21.0); // before the first step: the bird flies through the settle step
        session.step();
        EXPECT_FALSE(session.world().settleReused());
    }
    EXPECT_EQ(SettleCache::shared().size(), 0u);
}

TEST_F(SettleCacheTest, KeepsAtMostItsLimitInMemory)
{
    for (std::size_t i = 0; i < SettleCache::kMaxStates + 6; ++i)
        SettleCache::shared().store(i, std::make_shared<SettledState>());
    EXPECT_EQ(SettleCache::shared().size(), SettleCache::kMaxStates);
    EXPECT_EQ(SettleCache::shared().find(0), nullptr);
    EXPECT_NE(SettleCache::shared().find(SettleCache::kMaxStates + 5), nullptr);
}

} // namespace
} // namespace abalike

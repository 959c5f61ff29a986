#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <gtest/gtest.h>
#include <set>
#include <string>

namespace abalike
{
namespace
{

/// Levels whose first bird cannot defeat a pig with any first shot of tools/reference-shots' grid (angles -20 to 70
/// degrees by 2.5, 50 to 100 % of its top speed by 10 %): none since one band per world (2-1's red bird was the slow
/// half of its lesson). (5-5's first shot can since a breaking block hands its momentum on, 5-3's since a breaking
/// block yields to what strikes it.)
const std::set<std::string> kNoPigOnTheFirstShot = {};

/// Plays a level's reference shot until a pig is defeated or the shot is over; true when a pig was defeated.
bool referenceShotDefeatsAPig(const LevelDef& level)
{
    GameSession session(level);
    const int pigs = session.pigsRemaining();
    session.launch(level.referenceShot->angleDeg, level.referenceShot->speedMps);
    while (session.phase() == Phase::Flying && session.pigsRemaining() == pigs)
        session.step();
    return session.pigsRemaining() < pigs;
}

// A reference shot shows its level off: the gallery, the camera tests and `bench perf` replay it.
// tools/reference-shots picks one where a level's does not.
TEST(CampaignReferenceShots, EachDefeatsAPigWhereAFirstShotCan)
{
    const std::string dir = std::string(ABALIKE_SOURCE_DIR) + "/levels/";
    const std::vector<std::string> paths = loadCampaign(dir + "campaign.json");
    ASSERT_EQ(paths.size(), 50u);
    for (const std::string& path : paths)
    {
        const LevelDef level = loadLevel(path, Catalog::builtin());
        ASSERT_TRUE(level.referenceShot) << path;
        EXPECT_EQ(referenceShotDefeatsAPig(level), kNoPigOnTheFirstShot.count(level.id) == 0)
            << level.id << ": run tools/reference-shots";
    }
}

} // namespace
} // namespace abalike

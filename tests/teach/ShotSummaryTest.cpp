#include <abalike/game/GameSession.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/teach/ShotFeedback.hpp>
#include <gtest/gtest.h>
#include <string>

using namespace abalike;

TEST(ShotSummary, EveryReferenceShotsGistIsOneShortWholeSentenceThatAgreesWithTheFeedback)
{
    // The card short of room shows the gist instead of a sentence cut short: it must be whole, fit one line at the
    // default window (at most 72 characters), and say what the full sentence says about the bird.
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    int breaking = 0;
    for (const CampaignLevel& entry : campaign.levels)
    {
        const LevelDef& level = entry.level;
        SCOPED_TRACE(level.id);
        const auto session = simulateShots(level, {{level.referenceShot->angleDeg, level.referenceShot->speedMps}});
        const ShotRecord& shot = session->shots().at(0);
        const std::vector<std::string> full = shotFeedback(level, Catalog::builtin(), shot);
        const std::string gist = shotSummary(level, Catalog::builtin(), shot);
        ASSERT_FALSE(full.empty());
        ASSERT_FALSE(gist.empty());
        EXPECT_LE(gist.size(), 72u) << gist;
        EXPECT_EQ(gist.back(), '.') << gist;
        EXPECT_EQ(gist.find('{'), std::string::npos) << gist;
        const bool broke = full.front().find(" broke.") != std::string::npos ||
                           full.front().find(" was defeated.") != std::string::npos;
        const bool turned = full.front().find("it was turned back") != std::string::npos;
        if (broke && !turned)
        {
            EXPECT_NE(gist.find("and flew on"), std::string::npos) << gist << " | " << full.front();
            ++breaking;
        }
        if (broke && turned)
        {
            EXPECT_NE(gist.find("turned back"), std::string::npos) << gist << " | " << full.front();
        }
    }
    EXPECT_GT(breaking, 5); // the check above ran on real break-throughs
}

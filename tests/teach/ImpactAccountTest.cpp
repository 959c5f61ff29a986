#include <abalike/game/GameSession.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/ImpactAccount.hpp>
#include <abalike/teach/ShotFeedback.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <regex>
#include <string>

using namespace abalike;

namespace
{

double sizeOf(const Vec2& v)
{
    return std::hypot(v.x, v.y);
}

/// The whole number the sentence prints after `before` ("changed by 25 N·s" -> 25), or -1.
double numberAfter(const std::string& sentence, const std::string& before)
{
    const auto at = sentence.find(before);
    return at == std::string::npos ? -1.0 : std::stod(sentence.substr(at + before.size()));
}

/// Checks one shot's impact report as a teacher would, by Newton's third law and against the strength it names.
/// Returns true when the shot had an impact.
bool expectTheReportAddsUp(const LevelDef& level, const ShotRecord& shot)
{
    if (!shot.impact)
        return false;
    const FirstImpact& impact = *shot.impact;
    const ImpactAccount account = accountImpact(impact, Catalog::builtin());
    const std::string sentence = impactSentence(account);
    SCOPED_TRACE(sentence);
    // Exactly, before rounding: the bird's change is minus everything it pushed (Box2D works in float).
    Vec2 pushedByBird = account.exchanged + account.unnamed;
    for (const ImpactAccount::Partner& partner : account.partners)
        pushedByBird = pushedByBird + partner.impulse;
    EXPECT_LT(sizeOf(account.birdChange + pushedByBird), 1e-3 + 1e-5 * account.carriedBefore);
    // As read: the named impulses, each shown to the newton-second, add up to the change the sentence states.
    Vec2 named = account.exchanged;
    for (const ImpactAccount::Partner& partner : account.partners)
    {
        EXPECT_GT(sizeOf(partner.impulse), ImpactAccount::kNamedImpulseNs);
        named = named + partner.impulse;
    }
    const double rounding = 0.5 * static_cast<double>(1 + account.partners.size());
    EXPECT_LE(sizeOf(account.birdChange + named), rounding) << "unnamed pushes " << sizeOf(account.unnamed);
    EXPECT_NEAR(numberAfter(sentence, "changed by "), std::round(sizeOf(account.birdChange)), 0.5);
    EXPECT_NEAR(numberAfter(sentence, "each other with "), std::round(sizeOf(account.exchanged)), 0.5);
    // The body that broke cannot push back more than it could take (along the contact normal; friction acts
    // across it): the exchange is not the solver's push.
    if (impact.broke)
    {
        const double alongNormal = account.exchanged.x * impact.normal.x + account.exchanged.y * impact.normal.y;
        EXPECT_LE(alongNormal, impact.strengthBeforeNs * 1.01 + 0.5 + sizeOf(impact.handedOn)) << level.id;
    }
    // "all" only when the damage reached what the body could still take.
    const bool saysAll = sentence.find("took all") != std::string::npos;
    EXPECT_EQ(saysAll, impact.broke);
    if (!impact.broke && impact.damageNs > 0.0)
    {
        const std::string damage = damageOfStrength(impact.damageNs, impact.strengthBeforeNs);
        EXPECT_NE(damage.substr(0, damage.find(" of the")),
                  damage.substr(damage.find("the ") + 4, damage.find(" N") - damage.find("the ") - 4));
    }
    EXPECT_EQ(sentence.find("given back"), std::string::npos);
    EXPECT_EQ(sentence.find("-0"), std::string::npos);
    return true;
}

} // namespace

TEST(ImpactAccount, EveryImpactOfTheCampaignAddsUpByNewtonsThirdLaw)
{
    // Every campaign level's reference shot and a grid of first shots (15 to 60 degrees, 80 and 100 % of the first
    // bird's full pull): 450 shots, every first impact on a block or a pig a learner could read after them.
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    int impacts = 0;
    int broke = 0;
    int withPartners = 0;
    for (const CampaignLevel& entry : campaign.levels)
    {
        const LevelDef& level = entry.level;
        SCOPED_TRACE(level.id);
        const BirdType& bird = *Catalog::builtin().findBird(level.birds.front());
        const SlingshotBand band = slingshotBand(level, bird, Catalog::builtin());
        std::vector<ScriptedShot> shots{{level.referenceShot->angleDeg, level.referenceShot->speedMps}};
        for (const double angle : {15.0, 30.0, 45.0, 60.0})
            for (const double share : {0.8, 1.0})
                shots.push_back({angle, band.atFraction(share).speedMps});
        for (const ScriptedShot& shot : shots)
        {
            SCOPED_TRACE(std::to_string(shot.angleDeg) + "," + std::to_string(shot.speedMps));
            const auto session = simulateShots(level, {shot});
            const ShotRecord& record = session->shots().at(0);
            if (expectTheReportAddsUp(level, record))
            {
                ++impacts;
                broke += record.impact->broke ? 1 : 0;
                withPartners += accountImpact(*record.impact, Catalog::builtin()).partners.empty() ? 0 : 1;
            }
        }
    }
    EXPECT_GT(impacts, 150); // a shot that lands on the ground first has no impact to report: 170 of 450 strike
    EXPECT_GT(broke, 50);
    EXPECT_GT(withPartners, 0) << "no shot pushed a second body: the partners were never checked";
    std::printf("%d impacts, %d broke, %d with a second body named\n", impacts, broke, withPartners);
}

TEST(ImpactAccount, DamageIsNeverRoundedUpToAllOfIt)
{
    EXPECT_EQ(damageOfStrength(59.96, 60.0), "59.96 of the 60 N\u00B7s");
    EXPECT_EQ(damageOfStrength(45.2, 60.0), "45 of the 60 N\u00B7s");
    EXPECT_EQ(damageOfStrength(59.6, 60.0), "59.6 of the 60 N\u00B7s");
    EXPECT_EQ(damageOfStrength(60.0, 60.0), "60 of the 60 N\u00B7s");
}

TEST(ImpactAccount, OnFirstFlightTheIceBlockPushesBackOnlyWhatItCouldTake)
{
    // The teacher's case (1-1, 30 degrees at 18 m/s): the solver pushed with 71 N·s, the block that broke pushed
    // back 25 N·s, and the bird's momentum changed by exactly that (a vector: 71 -> 48 kg·m/s).
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    const LevelDef& level = campaign.levels.front().level;
    const auto session = simulateShots(level, {{30.0, 18.0}});
    const ShotRecord& shot = session->shots().at(0);
    ASSERT_TRUE(shot.impact);
    const ImpactAccount account = accountImpact(*shot.impact, Catalog::builtin());
    EXPECT_NEAR(sizeOf(shot.impact->balance.pushOnBody), 71.0, 1.0);
    EXPECT_NEAR(sizeOf(account.exchanged), 25.0, 0.5);
    EXPECT_NEAR(sizeOf(account.birdChange), 25.0, 0.5);
    EXPECT_NEAR(account.carriedBefore, 71.0, 0.5);
    EXPECT_NEAR(account.carriedAfter, 48.0, 0.5);
    const std::string sentence = impactSentence(account);
    EXPECT_NE(sentence.find("They pushed each other with 25 N\u00B7s, equal and opposite, before the ice block broke"),
              std::string::npos)
        << sentence;
    EXPECT_NE(sentence.find("changed by 25 N\u00B7s, from 71 to 48 kg\u00B7m/s"), std::string::npos) << sentence;
    EXPECT_EQ(sentence.find("71 N\u00B7s"), std::string::npos) << "the solver's push is not shown: " << sentence;
}

#include <abalike/game/GameSession.hpp>
#include <abalike/game/ReferenceShots.hpp>

#include <gtest/gtest.h>

namespace abalike
{
/// Names the shot in test output instead of dumping its bytes.
void PrintTo(const ReferenceShot& shot, std::ostream* out)
{
    *out << shot.name;
}

namespace
{

class ReferenceShotTest : public testing::TestWithParam<ReferenceShot>
{
};

TEST_P(ReferenceShotTest, PredictedAndActualFirstContactAgreeWithinOneCentimetre)
{
    const ReferenceShot& shot = GetParam();
    GameSession session(referenceShotLevel(shot));
    session.launch(shot.angleDeg, shot.speedMps);
    for (int i = 0; i < 20 * 60 && session.phase() == Phase::Flying && !session.shots().back().actualContact; ++i)
        session.step();
    const ShotRecord& record = session.shots().back();
    ASSERT_TRUE(record.predictedContact.has_value()) << shot.description;
    ASSERT_TRUE(record.actualContact.has_value()) << shot.description;
    ASSERT_TRUE(record.deviationM.has_value());
    EXPECT_LE(*record.deviationM, 0.01) << shot.description << ": predicted (" << record.predictedContact->x << ", "
                                        << record.predictedContact->y << "), actual (" << record.actualContact->x
                                        << ", " << record.actualContact->y << ")";
    EXPECT_NEAR(record.actualContact->t, record.predictedContact->t, 1.0 / 60.0);
    RecordProperty("deviation_mm", std::to_string(*record.deviationM * 1000.0));
}

INSTANTIATE_TEST_SUITE_P(Shots, ReferenceShotTest, testing::ValuesIn(referenceShots()),
                         [](const testing::TestParamInfo<ReferenceShot>& info)
                         {
                             std::string name;
                             for (const char c : info.param.name)
                                 name += c == '-' ? '_' : c;
                             return name;
                         });

TEST(ReferenceShots, CoverVacuumDragWindShortAndLong)
{
    bool vacuum = false, drag = false, wind = false, gusts = false, wall = false, ground = false;
    for (const ReferenceShot& shot : referenceShots())
    {
        vacuum |= shot.airDensity == 0.0;
        drag |= shot.airDensity > 0.0;
        wind |= shot.airDensity > 0.0 && (shot.windX != 0.0 || shot.windY != 0.0);
        gusts |= shot.gusts.has_value();
        wall |= shot.wallX.has_value();
        ground |= !shot.wallX.has_value();
    }
    EXPECT_TRUE(vacuum && drag && wind && gusts && wall && ground);
}

} // namespace
} // namespace abalike

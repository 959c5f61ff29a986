#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/PolygonPartition.hpp>
#include <abalike/world/RestCheck.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

double area(const std::vector<Vec2>& polygon)
{
    return 0.5 * std::abs(twiceSignedArea(polygon));
}

bool isConvex(const std::vector<Vec2>& p)
{
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec2& a = p[i];
        const Vec2& b = p[(i + 1) % p.size()];
        const Vec2& c = p[(i + 2) % p.size()];
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < -1e-12)
            return false;
    }
    return true;
}

const std::vector<Vec2> kHill{{14, 0}, {34, 0}, {34, 2}, {30, 4}, {27, 4}, {24, 2.5}, {20, 3.2}, {16, 1}};

TEST(PolygonPartition, AConvexPolygonStaysWholeEitherWinding)
{
    const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    ASSERT_EQ(convexPieces(square).size(), 1u);
    std::vector<Vec2> clockwise(square.rbegin(), square.rend());
    const auto pieces = convexPieces(clockwise);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_GT(twiceSignedArea(pieces[0]), 0.0) << "pieces are counter-clockwise";
}

TEST(PolygonPartition, AConcaveHillSplitsIntoConvexPiecesOfTheSameArea)
{
    const auto pieces = convexPieces(kHill);
    ASSERT_GE(pieces.size(), 2u);
    double sum = 0.0;
    for (const auto& piece : pieces)
    {
        EXPECT_TRUE(isConvex(piece));
        EXPECT_LE(piece.size(), 8u);
        sum += area(piece);
    }
    EXPECT_NEAR(sum, area(kHill), 1e-9);
    // Hertel-Mehlhorn keeps the count near the minimum: the hill has two reflex corners.
    EXPECT_LE(pieces.size(), 4u);
}

TEST(PolygonPartition, ManyCornersAreSplitIntoPiecesBox2DTakes)
{
    std::vector<Vec2> disc;
    for (int i = 0; i < 40; ++i)
        disc.push_back(
            {5.0 * std::cos(i * 2.0 * 3.141592653589793 / 40), 5.0 * std::sin(i * 2.0 * 3.141592653589793 / 40)});
    double sum = 0.0;
    for (const auto& piece : convexPieces(disc))
    {
        EXPECT_LE(piece.size(), 8u);
        sum += area(piece);
    }
    EXPECT_NEAR(sum, area(disc), 1e-9);
}

TEST(PolygonPartition, FindsTheCrossingOfABowtie)
{
    const auto crossing = firstCrossing({{0, 0}, {4, 4}, {4, 0}, {0, 4}});
    ASSERT_TRUE(crossing);
    EXPECT_EQ(crossing->first, 0u);
    EXPECT_EQ(crossing->second, 2u);
    EXPECT_FALSE(firstCrossing(kHill));
}

LevelDef hillLevel(const std::string& extra = "")
{
    return parseLevel(R"({"format": 1, "id": "hill", "title": "Hill", "slingshot": {"x": 0, "y": 1.5},
        "birds": ["red", "red"],
        "terrain": [{"points": [[14, 0], [34, 0], [34, 2], [30, 4], [27, 4], [24, 2.5], [20, 3.2], [16, 1]]}],
        "blocks": [{"material": "wood", "x": 28.0, "y": 4.75, "w": 0.25, "h": 1.5},
                   {"material": "wood", "x": 29.5, "y": 4.75, "w": 0.25, "h": 1.5},
                   {"material": "wood", "x": 28.75, "y": 5.625, "w": 2.0, "h": 0.25})" +
                          extra + R"(],
        "pigs": [{"type": "small", "x": 28.75, "y": 4.25}]})",
                      "hill.json", Catalog::builtin());
}

TEST(TerrainPolygon, LoadsWithItsBoundingBoxAndWritesBackItsPoints)
{
    const LevelDef level = hillLevel();
    ASSERT_EQ(level.terrain.size(), 1u);
    const TerrainDef& t = level.terrain[0];
    EXPECT_TRUE(t.isPolygon());
    EXPECT_DOUBLE_EQ(t.x, 24.0);
    EXPECT_DOUBLE_EQ(t.y, 2.0);
    EXPECT_DOUBLE_EQ(t.widthM, 20.0);
    EXPECT_DOUBLE_EQ(t.heightM, 4.0);
    const std::string written = writeLevelJson(level, "");
    EXPECT_NE(
        written.find(R"({"points": [[14, 0], [34, 0], [34, 2], [30, 4], [27, 4], [24, 2.5], [20, 3.2], [16, 1]]})"),
        std::string::npos)
        << written;
    EXPECT_EQ(written.find("\"w\": 20"), std::string::npos);
    EXPECT_EQ(parseLevel(written, "again.json", Catalog::builtin()).terrain, level.terrain);
}

TEST(TerrainPolygon, AStructureOnItsPlateauStands)
{
    const RestReport rest = checkRest(hillLevel());
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(TerrainPolygon, ABallOnItsSlopeRollsDownhill)
{
    // A wood ball (0.5 m) on the slope from (16, 1) to (20, 3.2): 28.8 degrees. It rolls down, to the left.
    const double slope = std::atan2(2.2, 4.0);
    const double r = 0.25;
    const double cx = 18.0 - r * std::sin(slope);
    const double cy = 1.0 + 2.0 * std::tan(slope) + r * std::cos(slope);
    char ball[200];
    std::snprintf(ball, sizeof ball, R"(, {"shape": "circle", "material": "wood", "x": %.6f, "y": %.6f, "w": 0.5})", cx,
                  cy);
    const LevelDef level = hillLevel(ball);
    GameWorld world(level, Catalog::builtin());
    for (int i = 0; i < 60; ++i)
        world.step();
    for (const Entity& e : world.entities())
        if (e.kind == EntityKind::Block && e.defIndex == 3)
        {
            ASSERT_NE(e.body, nullptr);
            EXPECT_LT(e.body->GetPosition().x, cx - 0.5) << "it rolled down the slope";
            EXPECT_LT(e.body->GetLinearVelocity().x, -1.0);
        }
}

TEST(TerrainPolygon, ThePreviewHitsTheHillWhereTheWorldDoes)
{
    GameSession session(hillLevel());
    const PredictedFlight predicted = session.preview(30.0, 14.0);
    ASSERT_TRUE(predicted.contact);
    EXPECT_GT(predicted.contact->x, 14.0);
    session.launch(30.0, 14.0);
    while (session.phase() == Phase::Flying && !session.shots()[0].actualContact)
        session.step();
    const ShotRecord& shot = session.shots()[0];
    ASSERT_TRUE(shot.actualContact);
    ASSERT_TRUE(shot.firstTouched);
    EXPECT_EQ(*shot.firstTouched, EntityKind::Terrain);
    ASSERT_TRUE(shot.deviationM);
    EXPECT_LT(*shot.deviationM, 0.01);
}

} // namespace
} // namespace abalike

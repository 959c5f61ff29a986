#include <abalike/world/GameWorld.hpp>
#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// What a hit did to a structure after a few seconds.
struct HitResult
{
    int loose = 0;     ///< blocks destroyed or moved at least 0.5 m from where they were built
    int destroyed = 0; ///< of those, destroyed
};

/// Flies a bird from s0 into the level (after its settle step), optionally exploding it at first contact, and
/// counts the blocks knocked loose after `seconds`.
HitResult hit(const LevelDef& level, const std::string& birdName, const FlightState& s0, bool explode,
              double seconds = 5.0)
{
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& bird = *Catalog::builtin().findBird(birdName);
    FlightModel model;
    model.massKg = bird.massKg;
    model.gravity = level.environment.gravity;
    world.launchBird(bird, model, s0);
    bool exploded = false;
    for (int i = 0; i < static_cast<int>(seconds * 60); ++i)
    {
        world.step();
        if (explode && !exploded && world.birdContact())
            exploded = world.activateAbility().has_value();
    }
    EXPECT_EQ(exploded, explode);
    HitResult result;
    for (const Entity& e : world.entities())
    {
        if (e.kind != EntityKind::Block)
            continue;
        const BlockDef& built = level.blocks[static_cast<std::size_t>(e.defIndex)];
        if (!e.alive)
        {
            ++result.destroyed;
            ++result.loose;
        }
        else if (std::hypot(e.body->GetPosition().x - built.x, e.body->GetPosition().y - built.y) >= 0.5)
            ++result.loose;
    }
    return result;
}

WallSpec tenByTen()
{
    WallSpec spec;
    spec.columns = 10;
    spec.rows = 10;
    return spec;
}

// Standing still must never be bought by freezing a structure: hit, it must still come apart. Thresholds are
// about half of what the world does (docs/world-physics.md, "Hit tests", has the figures before and after the
// wall and tower fixes: 81 / 30 / 24 / 24 loose blocks before, 75 / 10 / 24 / 24 after).

TEST(StructureHit, ABlackBirdExplodingAtATenByTenWallBlowsItApart)
{
    // Straight at the wall's face, 1.3 m up, exploding on contact: its blast (the catalog's explode block) at the
    // centre.
    const HitResult r = hit(wallScene(tenByTen()), "black", {{15.0, 1.3}, {20.0, 0.0}}, true);
    std::cout << "[ hit      ] 10 x 10 wall, black bird exploding: " << r.loose << " of 100 loose, " << r.destroyed
              << " destroyed\n";
    EXPECT_GE(r.loose, 35);
}

TEST(StructureHit, AHeavyBirdAtFullSpeedKnocksBricksOutOfATenByTenWall)
{
    // The black bird (8 kg) at the 15 m/s a 1200 N slingshot gives it.
    const HitResult r = hit(wallScene(tenByTen()), "black", {{15.0, 1.3}, {15.0, 0.0}}, false);
    std::cout << "[ hit      ] 10 x 10 wall, black bird at 15 m/s: " << r.loose << " of 100 loose, " << r.destroyed
              << " destroyed\n";
    EXPECT_GE(r.loose, 5);
}

TEST(StructureHit, AHeavyBirdAtFullSpeedBringsDownAnEightStoreyTower)
{
    // Into the wood column of the second storey: the mixed tower comes down and breaks as it lands.
    const LevelDef tower = storeyTowerScene({8, {"stone", "wood", "ice"}, {"wood"}});
    const HitResult r = hit(tower, "black", {{15.0, 2.6}, {15.0, 0.0}}, false);
    std::cout << "[ hit      ] 8-storey tower, black bird at 15 m/s: " << r.loose << " of 24 loose, " << r.destroyed
              << " destroyed\n";
    EXPECT_GE(r.loose, 12);
}

TEST(StructureHit, ABlackBirdExplodingAtAnEightStoreyTowerBringsItDown)
{
    const LevelDef tower = storeyTowerScene({8, {"stone", "wood", "ice"}, {"wood"}});
    const HitResult r = hit(tower, "black", {{15.0, 2.6}, {15.0, 0.0}}, true);
    std::cout << "[ hit      ] 8-storey tower, black bird exploding: " << r.loose << " of 24 loose, " << r.destroyed
              << " destroyed\n";
    EXPECT_GE(r.loose, 12);
}

} // namespace
} // namespace abalike

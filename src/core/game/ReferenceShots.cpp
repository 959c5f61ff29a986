#include <abalike/game/ReferenceShots.hpp>

namespace abalike
{

namespace
{

constexpr double kWallWidthM = 0.4;
constexpr double kWallHeightM = 10.0;

GustDef gustSteps()
{
    GustDef gusts;
    gusts.kind = GustDef::Kind::Steps;
    gusts.steps = {{0.4, 6.0, 0.0}, {1.1, -4.0, 2.0}, {1.8, 0.0, 0.0}};
    return gusts;
}

GustDef gustSine()
{
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    gusts.amplitudeX = 5.0;
    gusts.amplitudeY = 1.5;
    gusts.periodS = 1.3;
    return gusts;
}

std::vector<ReferenceShot> makeShots()
{
    // Air at sea level is 1.2 kg/m^3: c = 0.055 kg/m for the red bird.
    return {
        {.name = "vacuum-wall",
         .description = "vacuum, 20 m/s at 30 deg into a wall 15 m away",
         .angleDeg = 30.0,
         .speedMps = 20.0,
         .wallX = 15.0},
        {.name = "vacuum-long", .description = "vacuum, 25 m/s at 45 deg, 3.8 s to the ground", .speedMps = 25.0},
        {.name = "vacuum-fast",
         .description = "vacuum, 200 m/s at 2 deg into a wall 60 m away (the world sub-steps)",
         .angleDeg = 2.0,
         .speedMps = 200.0,
         .wallX = 60.0},
        {.name = "moon-long",
         .description = "Moon gravity 1.62 m/s^2, 12 m/s at 45 deg, 10.6 s to the ground",
         .speedMps = 12.0,
         .gravity = 1.62},
        {.name = "drag-wall",
         .description = "air 1.2 kg/m^3, 25 m/s at 30 deg into a wall 25 m away",
         .angleDeg = 30.0,
         .speedMps = 25.0,
         .airDensity = 1.2,
         .wallX = 25.0},
        {.name = "drag-long",
         .description = "air 1.2 kg/m^3, 40 m/s at 50 deg to the ground",
         .angleDeg = 50.0,
         .speedMps = 40.0,
         .airDensity = 1.2},
        {.name = "drag-light",
         .description = "air 1.2 kg/m^3, the light blue bird at 45 m/s, 35 deg, to the ground",
         .bird = "blue",
         .angleDeg = 35.0,
         .speedMps = 45.0,
         .airDensity = 1.2},
        {.name = "headwind-wall",
         .description = "air 1.2 kg/m^3, wind -8 m/s, 25 m/s at 30 deg into a wall 20 m away",
         .angleDeg = 30.0,
         .speedMps = 25.0,
         .airDensity = 1.2,
         .windX = -8.0,
         .wallX = 20.0},
        {.name = "tailwind-long",
         .description = "air 1.2 kg/m^3, wind (6, 2) m/s, the blue bird at 35 m/s, 60 deg, to the ground",
         .bird = "blue",
         .angleDeg = 60.0,
         .speedMps = 35.0,
         .airDensity = 1.2,
         .windX = 6.0,
         .windY = 2.0},
        {.name = "gust-steps-wall",
         .description = "air 1.2 kg/m^3, a gust that jumps three times, 28 m/s at 25 deg into a wall 30 m away",
         .bird = "yellow",
         .angleDeg = 25.0,
         .speedMps = 28.0,
         .airDensity = 1.2,
         .gusts = gustSteps(),
         .wallX = 30.0},
        {.name = "gust-sine-long",
         .description = "air 1.2 kg/m^3, wind 3 m/s plus a 1.3 s sine gust, 30 m/s at 55 deg to the ground",
         .bird = "white",
         .angleDeg = 55.0,
         .speedMps = 30.0,
         .airDensity = 1.2,
         .windX = 3.0,
         .gusts = gustSine()},
    };
}

} // namespace

const std::vector<ReferenceShot>& referenceShots()
{
    static const std::vector<ReferenceShot> shots = makeShots();
    return shots;
}

LevelDef referenceShotLevel(const ReferenceShot& shot)
{
    LevelDef level;
    level.id = "reference-" + shot.name;
    level.title = shot.description;
    level.groundY = 0.0;
    level.slingshot.x = 0.0;
    level.slingshot.y = 1.5;
    level.slingshot.maxForceN = 1.0e6; // with a massless band, the world's own speed limit is the only one
    level.slingshot.bandMassKg = 0.0;
    level.birds = {shot.bird};
    level.environment.gravity = shot.gravity;
    level.environment.airDensity = shot.airDensity;
    level.environment.windX = shot.windX;
    level.environment.windY = shot.windY;
    level.environment.gusts = shot.gusts;
    double farthest = 150.0;
    if (shot.wallX)
    {
        level.blocks.push_back(
            {BlockShape::Box, "stone", *shot.wallX, kWallHeightM / 2, kWallWidthM, kWallHeightM, 0.0, 0.1});
        farthest = *shot.wallX + 5.0;
    }
    level.pigs.push_back({"small", farthest, 0.25});
    return level;
}

} // namespace abalike

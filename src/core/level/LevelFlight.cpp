#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <sstream>
#include <utility>

namespace abalike
{

FlightModel levelFlightModel(const EnvironmentDef& environment, const BirdType& bird)
{
    FlightModel model;
    model.gravity = environment.gravity;
    model.massKg = bird.massKg;
    model.quadraticDrag = quadraticDragCoefficient(environment.airDensity, bird.dragCoefficient, bird.radiusM);
    model.windX = environment.windX;
    model.windY = environment.windY;
    model.gusts = environment.gusts;
    return model;
}

BandDef worldBand(const LevelDef& level, const Catalog& catalog)
{
    const SlingshotRules& rules = catalog.slingshot();
    return BandDef{rules.forceFor(worldThemeName(levelTheme(level))), rules.maxPullM, rules.bandMassKg};
}

BandDef levelBand(const LevelDef& level, const Catalog& catalog)
{
    const SlingshotDef& own = level.slingshot;
    const BandDef world = worldBand(level, catalog);
    return BandDef{own.maxForceN.value_or(world.maxForceN), own.maxPullM.value_or(world.maxPullM),
                   own.bandMassKg.value_or(world.bandMassKg)};
}

std::string ownBandWarning(const LevelDef& level, const Catalog& catalog)
{
    const SlingshotDef& own = level.slingshot;
    if (!own.ownsBand())
        return {};
    const BandDef theirs = worldBand(level, catalog);
    std::ostringstream text;
    text << "sets its own band (";
    const char* sep = "";
    if (own.maxForceN)
        text << std::exchange(sep, ", ") << "/slingshot/max_force_n " << *own.maxForceN << " N";
    if (own.maxPullM)
        text << std::exchange(sep, ", ") << "/slingshot/max_pull_m " << *own.maxPullM << " m";
    if (own.bandMassKg)
        text << std::exchange(sep, ", ") << "/slingshot/band_mass_kg " << *own.bandMassKg << " kg";
    text << "; the band of its world, " << worldThemeTitle(levelTheme(level)) << ", is " << theirs.maxForceN << " N at "
         << theirs.maxPullM << " m with " << theirs.bandMassKg
         << " kg moving): the same pull throws a bird differently here than on the world's other levels; remove "
            "the key(s) to use the world's band";
    return text.str();
}

SlingshotBand slingshotBand(const LevelDef& level, const BirdType& bird, const Catalog& catalog)
{
    return SlingshotBand(levelBand(level, catalog), bird.massKg, catalog.maxLaunchSpeedMps());
}

double maxLaunchSpeed(const LevelDef& level, const BirdType& bird, const Catalog& catalog)
{
    return slingshotBand(level, bird, catalog).maxSpeedMps();
}

} // namespace abalike

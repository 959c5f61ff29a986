#include <abalike/level/LevelFlight.hpp>

#include <algorithm>

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

double maxLaunchSpeed(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog)
{
    const double bySlingshot = slingshot.maxForceN * catalog.slingshotReleaseTimeS() / bird.massKg;
    return std::min(bySlingshot, catalog.maxLaunchSpeedMps());
}

} // namespace abalike

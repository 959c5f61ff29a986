#include <abalike/level/LevelFlight.hpp>

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

SlingshotBand slingshotBand(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog)
{
    return SlingshotBand(slingshot, bird.massKg, catalog.maxLaunchSpeedMps());
}

double maxLaunchSpeed(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog)
{
    return slingshotBand(slingshot, bird, catalog).maxSpeedMps();
}

} // namespace abalike

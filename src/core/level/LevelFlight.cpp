#include <abalike/level/LevelFlight.hpp>

#include <algorithm>
#include <box2d/b2_common.h>

namespace abalike
{

namespace
{
/// The same share of b2_maxTranslation the game session allows (GameSession::maxLaunchSpeed).
constexpr double kMaxTranslationShare = 0.95;
} // namespace

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

double maxLaunchSpeed(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog, double dtS)
{
    const double bySlingshot = slingshot.maxForceN * catalog.slingshotReleaseTimeS() / bird.massKg;
    const double byBox2d = kMaxTranslationShare * b2_maxTranslation / dtS;
    return std::min(bySlingshot, byBox2d);
}

} // namespace abalike

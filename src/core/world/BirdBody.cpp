#include <abalike/world/BirdBody.hpp>

#include <algorithm>
#include <sstream>

namespace abalike
{

BirdBody birdCollisionBody(const BirdType& bird, double lightestBodyKg)
{
    BirdBody body;
    body.trueRadiusM = bird.radiusM;
    body.trueMassKg = bird.massKg;
    body.radiusM = std::max(bird.radiusM, kMinBirdBodyRadiusM);
    body.massLimitKg = lightestBodyKg > 0.0 ? kMaxBirdMassRatio * lightestBodyKg : 0.0;
    body.massKg = body.massLimitKg > 0.0 ? std::min(bird.massKg, body.massLimitKg) : bird.massKg;
    return body;
}

std::string describeBirdBody(const BirdBody& body)
{
    if (!body.clamped())
        return {};
    const bool size = body.radiusClamped();
    const bool mass = body.massClamped();
    std::ostringstream out;
    out.precision(3);
    out << "Its flight uses the true "
        << (size && mass ? "size and mass"
            : size       ? "size"
                         : "mass")
        << "; Box2D collides it as ";
    if (size)
        out << "a " << 2.0 * body.radiusM << " m ball";
    if (size && mass)
        out << " of ";
    if (mass)
        out << body.massKg << " kg (10 x the lightest block or pig)";
    out << ", because ";
    if (size)
        out << "bodies under 0.1 m slip through its contact skin";
    if (size && mass)
        out << " and ";
    if (mass)
        out << "a body over 10 times heavier than the one under it breaks its solver";
    out << '.';
    return out.str();
}

} // namespace abalike

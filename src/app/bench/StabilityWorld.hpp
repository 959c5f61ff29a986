#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// A group of extreme launches in the Box2D world, summarised.
struct WorldStabilityRow
{
    std::string group;
    std::string launches; ///< what was launched, e.g. "red at 0 .. 864 m/s, 10 speeds"
    int runs = 0;
    bool anyNonFinite = false;      ///< a NaN or infinity in any body at any step
    double worstPenetrationM = 0.0; ///< deepest the bird's leading edge got into the wall (or below the ground)
    bool tunnelled = false;         ///< the bird's centre got past the wall (or the ground) while it stood
    int contactsCompared = 0;       ///< launches where the preview and the world both found a first contact
    double worstDeviationM = 0.0;   ///< predicted vs actual first contact, worst launch
    int wallsBroken = 0;            ///< dynamic stone walls destroyed by the hit (a fair way through)
    bool passed = false;
};

/// Launches every bird at speeds up to the world's limit into a 0.2 m stone wall (static and dynamic), at every
/// angle from -90 to 90 degrees, under gravity 0 / 0.01 / 100, and birds of 0.1 g and 10 t.
std::vector<WorldStabilityRow> runWorldStability(bool quick);

} // namespace abalike::app

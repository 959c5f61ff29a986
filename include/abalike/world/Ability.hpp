#pragma once

#include <string>
#include <vector>

namespace abalike
{

/// One impulse an ability applied, or the momentum it gave a body it created, for the teaching overlay.
struct AbilityImpulse
{
    double tS = 0.0; ///< time since launch
    double x = 0.0;  ///< where it acts (m)
    double y = 0.0;
    double impulseX = 0.0; ///< N s
    double impulseY = 0.0;
    std::string target; ///< "bird", "split bird", "egg", "block" or "pig"
};

/// What using a bird's ability did.
struct AbilityUse
{
    std::string ability; ///< "split", "boost", "explode" or "egg"
    double tS = 0.0;     ///< time since launch
    double x = 0.0;      ///< where the bird was
    double y = 0.0;
    bool beforeContact = false; ///< used before the bird's first contact
    /// The launched bird's own flight changed before its first contact (boost, egg, explode; not split), so its
    /// first contact can no longer be compared with the prediction made at launch.
    bool changedFlight = false;
    std::vector<AbilityImpulse> impulses;
};

} // namespace abalike

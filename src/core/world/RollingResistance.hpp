#pragma once

#include <abalike/world/Entity.hpp>
#include <vector>

namespace abalike
{

/// Rolling resistance for the round bodies of a level (pigs and circle blocks; birds roll freely), applied after
/// each Box2D step: a torque of at most coefficient x normal force x radius against the body's spin, as a soft
/// pig or a ball on masonry feels. Box2D 2.4 has none, so a pig resting where two blocks meet, or on a block that
/// tilts by a hundredth of a degree, would roll away from a standing structure and pull the blocks it rests on
/// along; real balls on such slopes stay put (docs/world-physics.md, "Walls and mixed towers").
void resistRolling(const std::vector<Entity>& entities, double coefficient);

} // namespace abalike

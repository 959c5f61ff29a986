#pragma once

#include <abalike/edit/SceneObject.hpp>

#include <optional>
#include <vector>

namespace abalike
{

class Catalog;

/// How the editor snaps objects it places or moves.
struct SnapSettings
{
    bool grid = true;
    double gridM = 0.25;  ///< grid spacing (m)
    bool surfaces = true; ///< rest objects on the surface below and against neighbours
    /// A surface this close (m) pulls an object onto it (the editor sets at most 0.1); with the grid on, the surface
    /// below pulls from at least one grid step.
    double surfaceReachM = 0.25;
    double rotationStepDeg = 15.0; ///< rotations snap to multiples of this when grid is on
};

/// Where snapping put an object and what it now touches.
struct SnapResult
{
    double x = 0.0; ///< the object's centre after snapping
    double y = 0.0;
    bool onGround = false;                ///< it rests on the ground line
    std::optional<ObjectRef> restsOn;     ///< the object it rests on
    std::optional<ObjectRef> touchesSide; ///< the neighbour it was pushed against, left or right
};

/// Snaps an object whose centre is proposed at def's position: the lower-left corner of its bounding box to the grid,
/// then its bottom onto the highest surface under it within reach (an object or the ground), then its side against
/// the nearest neighbour within reach, then onto the surface under it again. Resting is exact: a box snapped onto a
/// box has its bottom at the other's top to the last bit the arithmetic allows, so the stack passes the rest test.
/// Objects in `ignore` (the ones being moved) are no surface; the slingshot only snaps to the grid.
SnapResult snapObject(const LevelDef& level, const Catalog& catalog, const ObjectDef& def,
                      const std::vector<ObjectRef>& ignore, const SnapSettings& settings);

/// Rounds a length to a whole nanometre, so that editor arithmetic such as 0.1 + 0.2 is written as the decimal a
/// designer expects (0.3), far below anything the physics resolves.
double cleanMetres(double value);

/// Rounds an angle to a step (degrees), and to a whole nano-degree.
double snapAngle(double angleDeg, double stepDeg);

} // namespace abalike

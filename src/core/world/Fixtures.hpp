#pragma once

#include <abalike/level/LevelDef.hpp>
#include <box2d/box2d.h>
#include <vector>

namespace abalike
{

/// User data that points a body back at its entity (index + 1, so 0 means "not an entity").
b2BodyUserData userDataFor(int entityIndex);

/// A convex polygon fixture for a designed outline (counter-clockwise), inset for Box2D's skin and with the
/// corners marked in chamferCorners (all when empty) cut by chamferM (Skin.hpp).
void addPolygonFixture(b2Body* body, const std::vector<b2Vec2>& outline, const b2FixtureDef& base, float chamferM,
                       const std::vector<bool>& chamferCorners = {});

/// A w x h box fixture centred at (cx, cy) in body coordinates, inset for the skin; corners as above, counted
/// counter-clockwise from the bottom left.
void addBoxFixture(b2Body* body, double w, double h, const b2FixtureDef& base, float chamferM, double cx = 0.0,
                   double cy = 0.0, const std::vector<bool>& chamferCorners = {});

/// A circle fixture of the designed radius, grown for the skin.
void addCircleFixture(b2Body* body, double radius, const b2FixtureDef& base);

/// The fixtures of a block's shape, centred on the body's origin (the centre of the block's bounding box), with
/// the corners of its outline cut by chamferM.
void addBlockFixtures(b2Body* body, const BlockDef& block, const b2FixtureDef& base, float chamferM);

/// Area of a block's designed outline (m^2): what its mass is computed from.
double designedArea(const BlockDef& block);

/// Scales the densities of a body's fixtures so that its mass is exactly massKg. The skin adjustments make
/// polygons a little smaller and circles a little larger than designed; mass must follow the design, not them.
void setBodyMass(b2Body* body, double massKg);

} // namespace abalike

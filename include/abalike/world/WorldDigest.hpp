#pragma once

#include <abalike/world/GameWorld.hpp>
#include <string>

namespace abalike
{

/// A fingerprint of every body in the world, as 16 hex digits: what each is, whether it is still there, and the
/// exact bits of its position, angle, velocity and health. Two runs that end with the same digest ended with the
/// same bodies in the same places (the simulate/play timing contract, docs/cli.md).
std::string bodiesDigest(const GameWorld& world);

} // namespace abalike

#pragma once

#include "level/LevelReader.hpp"

#include <abalike/level/LevelDef.hpp>

namespace abalike
{

class Catalog;

/// Reads "environment" (gravity, air, wind, gusts) into level.environment; absent parts keep their defaults.
void readEnvironment(LevelReader& reader, const nlohmann::json& root, LevelDef& level);

/// Reads "materials" (this level's values for catalog materials) into level.materials, in the catalog's order.
void readMaterialOverrides(LevelReader& reader, const nlohmann::json& root, LevelDef& level, const Catalog& catalog);

/// Reads "custom_bird" (mass, diameter, drag coefficient) into level.customBird.
void readCustomBird(LevelReader& reader, const nlohmann::json& root, LevelDef& level);

/// Semantic checks of a level that parsed cleanly: overlapping bodies, bodies beyond the world bounds, pigs no
/// launch can reach, a slingshot inside something, a reference shot faster than the slingshot allows.
void checkLevel(const LevelDef& level, const Catalog& catalog, LevelReader& reader);

} // namespace abalike

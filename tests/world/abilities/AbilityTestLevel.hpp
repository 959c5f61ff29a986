#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/world/Ability.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::test
{

/// A level with one bird of each kind and a wood tower 20 m away.
inline LevelDef abilityLevel(std::vector<std::string> birds)
{
    LevelDef level;
    level.birds = std::move(birds);
    for (int i = 0; i < 4; ++i)
        level.blocks.push_back({BlockShape::Box, "wood", 20.0, 0.5 + i, 0.5, 1.0, 0.0});
    level.pigs = {{"small", 21.0, 0.25}, {"small", 40.0, 0.25}};
    return level;
}

/// Launches the only bird and steps until `seconds` after launch.
inline void launchAndFly(GameSession& session, double angleDeg, double speedMps, double seconds)
{
    session.launch(angleDeg, speedMps);
    while (session.timeSinceLaunch() < seconds - 1e-9)
        session.step();
}

/// The bird's velocity over the last step, from its recorded path.
inline Vec2 pathVelocity(const ShotRecord& shot)
{
    const auto& a = shot.actualPath[shot.actualPath.size() - 2];
    const auto& b = shot.actualPath.back();
    return {(b.position.x - a.position.x) / (b.timeS - a.timeS), (b.position.y - a.position.y) / (b.timeS - a.timeS)};
}

/// One of an ability's numbers as the catalog gives it.
inline double numberOf(const Catalog& catalog, std::string_view ability, std::string_view key)
{
    const Ability* found = catalog.findAbility(ability);
    if (found == nullptr)
        throw std::runtime_error("no ability " + std::string(ability));
    return found->number(key);
}

inline double angleOf(double x, double y)
{
    return std::atan2(y, x) * 180.0 / std::numbers::pi;
}

} // namespace abalike::test

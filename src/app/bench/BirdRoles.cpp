// `abalike bench feel`, the birds' roles: does each bird break the material it is for? Every bird at full pull
// against a lone block of every material, over a fan of aims that hit it directly; the black bird's blast set off
// at the moment it touches stone; the yellow bird boosted and the blue bird's split birds against their materials.
#include "bench/BirdRoles.hpp"

#include <abalike/game/GameSession.hpp>
#include <cmath>

namespace abalike::app
{

namespace
{

/// The block stands this far from the slingshot, on flat ground.
constexpr double kBlockX = 10.0;

/// A lone block of a material, 1 m square, on the ground in front of a bird of one kind.
LevelDef loneBlock(const std::string& bird, const std::string& material)
{
    LevelDef level;
    level.id = "role-" + bird + "-" + material;
    level.birds = {bird};
    level.blocks.push_back({BlockShape::Box, material, kBlockX, 0.5, 1.0, 1.0, 0.0, 0.1});
    level.pigs.push_back({"small", kBlockX + 20.0, 0.25}); // out of the way: the level must have a pig
    return level;
}

struct Trial
{
    bool direct = false; ///< the bird's first contact was the block
    bool broke = false;  ///< the block broke during the shot
};

/// One full-pull shot at angleDeg; the ability is used abilityDelayS after launch, or at the first contact when the
/// delay is negative (the blast), or not at all.
Trial fire(const LevelDef& level, double angleDeg, std::optional<double> abilityAtS, bool atContact)
{
    GameSession session(level);
    session.launch(angleDeg, session.maxLaunchSpeed());
    Trial trial;
    bool used = false;
    while (session.phase() == Phase::Flying && session.timeSinceLaunch() < 4.0)
    {
        if (!used && abilityAtS && session.timeSinceLaunch() >= *abilityAtS - 1e-9)
            used = session.activateAbility();
        session.step();
        if (!used && atContact && session.world().birdContact())
            used = session.activateAbility();
        for (const DestroyedEvent& event : session.destroyed())
            trial.broke |= event.kind == EntityKind::Block;
    }
    const ShotRecord& shot = session.shots().front();
    trial.direct = shot.firstTouched && *shot.firstTouched == EntityKind::Block;
    return trial;
}

} // namespace

RoleRow measureRole(const std::string& bird, const std::string& material, RoleUse use)
{
    const LevelDef level = loneBlock(bird, material);
    RoleRow row{bird, material, use, 0, 0};
    // Aims from flat to steep in half-degree steps; only direct hits count.
    for (double angle = -5.0; angle <= 45.0; angle += 0.5)
    {
        Trial trial;
        switch (use)
        {
        case RoleUse::DirectHit:
            trial = fire(level, angle, std::nullopt, false);
            break;
        case RoleUse::AbilityEarly:
            trial = fire(level, angle, 0.1, false);
            break;
        case RoleUse::AbilityAtContact:
            trial = fire(level, angle, std::nullopt, true);
            break;
        }
        if (!trial.direct)
            continue;
        ++row.directHits;
        row.broke += trial.broke ? 1 : 0;
    }
    return row;
}

const char* roleUseName(RoleUse use)
{
    switch (use)
    {
    case RoleUse::DirectHit:
        return "direct hit";
    case RoleUse::AbilityEarly:
        return "ability 0.1 s after launch";
    case RoleUse::AbilityAtContact:
        return "ability at the first contact";
    }
    return "";
}

} // namespace abalike::app

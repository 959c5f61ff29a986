#pragma once

#include <string>

namespace abalike::app
{

/// How a bird is used against a block in `bench feel`'s roles table.
enum class RoleUse
{
    DirectHit,        ///< flies into it at full pull
    AbilityEarly,     ///< uses its ability 0.1 s after launch (the split, the boost), then flies into it
    AbilityAtContact, ///< uses its ability the moment it touches it (the blast)
};

const char* roleUseName(RoleUse use);

/// Full-pull shots of one bird at a lone 1 m block of one material over a fan of aims: how many hit it directly,
/// and how many of those broke it.
struct RoleRow
{
    std::string bird;
    std::string material;
    RoleUse use = RoleUse::DirectHit;
    int directHits = 0;
    int broke = 0;
};

RoleRow measureRole(const std::string& bird, const std::string& material, RoleUse use);

} // namespace abalike::app

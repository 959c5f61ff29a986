#pragma once

#include "render/Mesh.hpp"

#include <SFML/System/Vector2.hpp>
#include <abalike/world/Ability.hpp>
#include <abalike/world/Entity.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// What an ability's look may set off when the ability is used; the effects layer implements it.
class AbilityEffects
{
public:
    virtual ~AbilityEffects() = default;
    /// A flash and a burst of debris as wide as radiusM around centreM (world metres).
    virtual void burst(sf::Vector2f centreM, float radiusM) = 0;
    /// Shakes the world's picture by about px window pixels (nothing when the player asked for reduced motion).
    virtual void shake(float px) = 0;
};

/// How an ability looks in the game: each ability that draws or shows something of its own has one file under
/// src/app/render/abilities/ and a line in its table (abilityLookTable). An ability without one is drawn and
/// shown by the defaults here.
class AbilityLook
{
public:
    virtual ~AbilityLook() = default;

    /// Draws a body the ability added (an egg) in the mesh's local frame; false draws it as a bird of its type
    /// (split birds).
    virtual bool paintBody(Mesh& mesh, const Entity& body, float pixelM) const;
    /// Adds to a bird that has the ability (the black bird's fuse), radius r, in the bird's frame.
    virtual void decorateBird(Mesh& mesh, float r) const;
    /// When the ability is used: by default a use that reached out (AbilityUse::reachM, a blast) flashes as wide
    /// as it reached and shakes the view.
    virtual void onUse(AbilityEffects& effects, const AbilityUse& use) const;
};

/// The look registered for an ability, or the default look.
const AbilityLook& abilityLook(std::string_view ability);
/// True when an ability has a look of its own.
bool hasAbilityLook(std::string_view ability);

/// One line of the table of looks: an ability's name in the catalog and the function that makes its look.
struct AbilityLookTableEntry
{
    std::string_view ability;
    std::unique_ptr<AbilityLook> (*make)();
};

/// Every ability's own look: an explicit table (src/app/render/abilities/AbilityLookTable.cpp), so linking the app
/// in any way keeps them all.
const std::vector<AbilityLookTableEntry>& abilityLookTable();

} // namespace abalike::app

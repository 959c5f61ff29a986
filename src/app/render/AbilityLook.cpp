#include "render/AbilityLook.hpp"

#include <map>
#include <stdexcept>

namespace abalike::app
{

namespace
{

const std::map<std::string, std::unique_ptr<AbilityLook>, std::less<>>& looks()
{
    static const std::map<std::string, std::unique_ptr<AbilityLook>, std::less<>> byAbility = []
    {
        std::map<std::string, std::unique_ptr<AbilityLook>, std::less<>> made;
        for (const AbilityLookTableEntry& entry : abilityLookTable())
            if (!made.emplace(std::string(entry.ability), entry.make()).second)
                throw std::logic_error("look of ability \"" + std::string(entry.ability) + "\" is in the table twice");
        return made;
    }();
    return byAbility;
}

} // namespace

bool AbilityLook::paintBody(Mesh& mesh, const Entity& body, float pixelM) const
{
    (void)mesh;
    (void)body;
    (void)pixelM;
    return false;
}

void AbilityLook::decorateBird(Mesh& mesh, float r) const
{
    (void)mesh;
    (void)r;
}

void AbilityLook::onUse(AbilityEffects& effects, const AbilityUse& use) const
{
    if (use.reachM <= 0.0)
        return;
    effects.burst({static_cast<float>(use.x), static_cast<float>(use.y)}, static_cast<float>(use.reachM));
    effects.shake(12.0f);
}

const AbilityLook& abilityLook(std::string_view ability)
{
    static const AbilityLook plain;
    const auto it = looks().find(ability);
    return it == looks().end() ? plain : *it->second;
}

bool hasAbilityLook(std::string_view ability)
{
    return looks().find(ability) != looks().end();
}

} // namespace abalike::app

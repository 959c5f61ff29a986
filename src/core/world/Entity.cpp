#include <abalike/world/Ability.hpp>
#include <abalike/world/Entity.hpp>

namespace abalike
{

const char* entityKindName(EntityKind kind)
{
    switch (kind)
    {
    case EntityKind::Ground:
        return "ground";
    case EntityKind::Terrain:
        return "terrain";
    case EntityKind::Block:
        return "block";
    case EntityKind::Pig:
        return "pig";
    case EntityKind::Bird:
        return "bird";
    }
    return "unknown";
}

const char* causeKindName(CauseKind kind)
{
    switch (kind)
    {
    case CauseKind::Bird:
        return "bird";
    case CauseKind::Block:
        return "block";
    case CauseKind::Pig:
        return "pig";
    case CauseKind::Explosion:
        return "explosion";
    case CauseKind::Ability:
        return "ability";
    case CauseKind::Ground:
        return "ground";
    case CauseKind::OutOfBounds:
        return "out_of_bounds";
    }
    return "ground";
}

std::string causeName(const DefeatCause& cause)
{
    if (cause.kind == CauseKind::Ability && cause.ability != nullptr)
        return std::string(cause.ability->name());
    return causeKindName(cause.kind);
}

} // namespace abalike

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
    case CauseKind::Egg:
        return "egg";
    case CauseKind::Ground:
        return "ground";
    case CauseKind::OutOfBounds:
        return "out_of_bounds";
    }
    return "ground";
}

} // namespace abalike

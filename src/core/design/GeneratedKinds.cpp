#include <abalike/design/GeneratorLayouts.hpp>

namespace abalike
{

const char* generatedKindName(GeneratedKind kind)
{
    switch (kind)
    {
    case GeneratedKind::Towers:
        return "towers";
    case GeneratedKind::Castle:
        return "castle";
    case GeneratedKind::Cages:
        return "cages";
    case GeneratedKind::Pyramid:
        return "pyramid";
    case GeneratedKind::Bridge:
        return "bridge";
    case GeneratedKind::Hill:
        return "hill";
    case GeneratedKind::Island:
        return "island";
    case GeneratedKind::TntStore:
        return "tnt store";
    }
    return "towers";
}

const std::vector<GeneratedKind>& generatedKinds()
{
    static const std::vector<GeneratedKind> kinds{GeneratedKind::Towers,  GeneratedKind::Castle,  GeneratedKind::Cages,
                                                  GeneratedKind::Pyramid, GeneratedKind::Bridge,  GeneratedKind::Hill,
                                                  GeneratedKind::Island,  GeneratedKind::TntStore};
    return kinds;
}

std::string kindHint(GeneratedKind kind)
{
    switch (kind)
    {
    case GeneratedKind::Towers:
        return "The towers stand close: hit the first one high and it falls onto the next.";
    case GeneratedKind::Castle:
        return "Stone walls hold; knock out what they stand on, or bring the black bird.";
    case GeneratedKind::Cages:
        return "Each cage is light: a flat shot can go through several.";
    case GeneratedKind::Pyramid:
        return "The pyramids shield the frames: go over them or push them into the frames.";
    case GeneratedKind::Bridge:
        return "Knock out a column and the bridge comes down on the pig beneath.";
    case GeneratedKind::Hill:
        return "The structure stands on a hill: aim a little higher than on flat ground.";
    case GeneratedKind::Island:
        return "The island floats: what you push off its edge falls a long way.";
    case GeneratedKind::TntStore:
        return "Hit the TNT crate: its blast breaks what stands around it.";
    }
    return "";
}

} // namespace abalike

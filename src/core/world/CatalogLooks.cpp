#include "world/CatalogLooks.hpp"

#include "level/LevelReader.hpp"

#include <array>
#include <nlohmann/json.hpp>
#include <vector>

namespace abalike
{

namespace
{

using nlohmann::json;

constexpr std::array<SurfaceKind, 4> kSurfaceKinds{SurfaceKind::Grain, SurfaceKind::Frost, SurfaceKind::Masonry,
                                                   SurfaceKind::Crate};

const json& lookOf(const json& item, const std::string& pointer)
{
    if (!item.contains("look") || !item.at("look").is_object())
        throw CatalogError{pointer, "needs a \"look\" object (how the game draws it: docs/extending.md)"};
    return item.at("look");
}

int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

Rgba colour(const json& look, const char* key, const std::string& pointer)
{
    const std::string where = pointer + "/look/" + key;
    if (!look.contains(key))
        throw CatalogError{pointer + "/look", std::string("missing \"") + key + "\" (a colour \"#rrggbb\")"};
    const json& value = look.at(key);
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    Rgba rgba{0, 0, 0, 255};
    const bool shaped = value.is_string() && (text.size() == 7 || text.size() == 9) && text[0] == '#';
    for (std::size_t i = 0; shaped && i + 1 < text.size(); i += 2)
    {
        const int hi = hexDigit(text[i + 1]);
        const int lo = i + 2 < text.size() ? hexDigit(text[i + 2]) : -1;
        if (hi < 0 || lo < 0)
            throw CatalogError{where, "expected a colour \"#rrggbb\" or \"#rrggbbaa\", got " + value.dump()};
        rgba[i / 2] = static_cast<std::uint8_t>(16 * hi + lo);
    }
    if (!shaped)
        throw CatalogError{where, "expected a colour \"#rrggbb\" or \"#rrggbbaa\", got " + value.dump()};
    return rgba;
}

SurfaceKind surface(const json& look, const std::string& pointer)
{
    const std::string where = pointer + "/look/surface";
    const std::string name = look.value("surface", std::string());
    std::vector<std::string> names;
    for (const SurfaceKind kind : kSurfaceKinds)
    {
        if (surfaceKindName(kind) == name)
            return kind;
        names.emplace_back(surfaceKindName(kind));
    }
    std::string message = "unknown surface \"" + name + "\"";
    if (const auto suggestion = closestMatch(name, names))
        throw CatalogError{where, message + " (did you mean \"" + *suggestion + "\"?)"};
    message += " (expected one of:";
    for (std::size_t i = 0; i < names.size(); ++i)
        message += (i == 0 ? " " : ", ") + names[i];
    throw CatalogError{where, message + ")"};
}

} // namespace

std::string_view surfaceKindName(SurfaceKind kind)
{
    switch (kind)
    {
    case SurfaceKind::Grain:
        return "grain";
    case SurfaceKind::Frost:
        return "frost";
    case SurfaceKind::Masonry:
        return "masonry";
    case SurfaceKind::Crate:
        return "crate";
    }
    return "grain";
}

MaterialLook readMaterialLook(const json& material, const std::string& pointer)
{
    const json& look = lookOf(material, pointer);
    MaterialLook result;
    result.surface = surface(look, pointer);
    result.fill = colour(look, "fill", pointer);
    result.outline = colour(look, "outline", pointer);
    result.detail = colour(look, "detail", pointer);
    result.highlight = colour(look, "highlight", pointer);
    result.label = look.value("label", material.value("name", std::string()));
    return result;
}

BirdLook readBirdLook(const json& bird, const std::string& pointer)
{
    const json& look = lookOf(bird, pointer);
    return {colour(look, "body", pointer), colour(look, "outline", pointer), colour(look, "belly", pointer),
            colour(look, "brow", pointer)};
}

} // namespace abalike

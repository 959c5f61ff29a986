#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace abalike
{

/// A colour from the catalog: red, green, blue, alpha (0-255), written "#rrggbb" or "#rrggbbaa".
using Rgba = std::array<std::uint8_t, 4>;

/// How a material's surface is drawn, breaks and sounds. The game's painters, debris and sounds branch on this,
/// never on a material's name; a new material picks the kind it looks like (docs/extending.md).
enum class SurfaceKind
{
    Grain,   ///< wood: grain lines, splinters, a hollow knock
    Frost,   ///< ice: translucent with a glint, shards, a glassy ring
    Masonry, ///< stone: speckles, chunks, a dull thud
    Crate,   ///< a painted crate (TNT): planks and a warning label
};

/// The catalog's name of a surface kind ("grain", ...).
std::string_view surfaceKindName(SurfaceKind kind);

/// How a material looks in the game (the catalog's "look").
struct MaterialLook
{
    SurfaceKind surface = SurfaceKind::Grain;
    Rgba fill{214, 190, 140, 255};
    Rgba outline{140, 118, 80, 255};
    Rgba detail{186, 160, 112, 255};    ///< grain, speckles
    Rgba highlight{236, 218, 180, 255}; ///< a glint, chips
    std::string label;                  ///< its name in menus ("Wood", "TNT")
};

/// How a bird looks (the catalog's "look"). A level's custom bird has the default: red's.
struct BirdLook
{
    Rgba body{214, 36, 36, 255};
    Rgba outline{120, 14, 14, 255};
    Rgba belly{240, 214, 180, 255};
    Rgba brow{24, 14, 10, 255};
};

} // namespace abalike

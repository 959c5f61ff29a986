#pragma once

#include <abalike/world/Catalog.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// The catalog as Markdown tables (materials with their real-world basis, density ratios against Box2D's 10:1
/// guidance, birds, abilities, pigs, damage and scoring): docs/materials.md is this text.
std::string catalogMarkdown(const Catalog& catalog);

/// The parts other docs embed between `<!-- catalog:NAME -->` and `<!-- /catalog:NAME -->` (tests/docs/ checks
/// and regenerates them): "materials", "birds", "launch" (the default band, every bird), "abilities", "pigs" and
/// "bird-abilities" (one line: which bird has which ability), "bird-names" and "material-names" (`red`, `blue`, ...).
std::vector<std::string_view> catalogDocSectionNames();

/// The part of that name; nullopt for a name that is not one.
std::optional<std::string> catalogDocSection(const Catalog& catalog, std::string_view name);

} // namespace abalike

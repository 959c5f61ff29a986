#pragma once

#include <abalike/world/Catalog.hpp>
#include <string>

namespace abalike
{

/// The catalog as Markdown tables (materials with their real-world basis, density ratios against Box2D's 10:1
/// guidance, birds, abilities, pigs, damage and scoring): docs/materials.md is this text.
std::string catalogMarkdown(const Catalog& catalog);

} // namespace abalike

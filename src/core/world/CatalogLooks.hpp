#pragma once

#include <abalike/world/Looks.hpp>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace abalike
{

/// A name or value in the catalog that Catalog::fromJson reports at its line and column.
struct CatalogError
{
    std::string pointer; ///< JSON pointer of the value
    std::string message;
};

/// The "look" of the material at pointer (e.g. "/materials/0"); throws CatalogError.
MaterialLook readMaterialLook(const nlohmann::json& material, const std::string& pointer);
/// The "look" of the bird at pointer (e.g. "/birds/2"); throws CatalogError.
BirdLook readBirdLook(const nlohmann::json& bird, const std::string& pointer);

} // namespace abalike

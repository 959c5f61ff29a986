#pragma once

#include <abalike/world/Catalog.hpp>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace abalike::test
{

/// The bundled catalog, changed by `edit` (for tests that need, say, an unbreakable or perfectly elastic material).
inline Catalog catalogWith(const std::function<void(nlohmann::json&)>& edit)
{
    std::ifstream in(std::string(ABALIKE_SOURCE_DIR) + "/assets/catalog.json");
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json root = nlohmann::json::parse(text.str());
    edit(root);
    return Catalog::fromJson(root.dump());
}

/// The material named `name` in a catalog's JSON.
inline nlohmann::json& materialIn(nlohmann::json& root, const std::string& name)
{
    for (nlohmann::json& m : root["materials"])
        if (m["name"] == name)
            return m;
    throw std::runtime_error("no material " + name);
}

} // namespace abalike::test

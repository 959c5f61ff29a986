#pragma once

#include <abalike/world/Catalog.hpp>
#include <stdexcept>
#include <string>

namespace abalike::test
{

/// The message Catalog::fromJson throws for this catalog text; empty when it loads.
inline std::string catalogLoadError(const std::string& text)
{
    try
    {
        Catalog::fromJson(text);
    }
    catch (const std::runtime_error& e)
    {
        return e.what();
    }
    return "";
}

} // namespace abalike::test

#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// The value every item shares, or nullopt when they differ (or there are none): a multi-selection's field shows a
/// shared value as it is and a mixed one as "mixed".
template <class Item, class Get>
auto sharedValue(const std::vector<Item>& items, Get get) -> std::optional<decltype(get(items.front()))>
{
    if (items.empty())
        return std::nullopt;
    const auto first = get(items.front());
    for (const Item& item : items)
        if (!(get(item) == first))
            return std::nullopt;
    return first;
}

/// A number field for a multi-selection: with a shared value an ordinary field (true as it changes); with mixed
/// values an empty field hinted "mixed", which changes nothing until a number is typed and confirmed (Enter or
/// leaving the field), then gives it in value and returns true. released: set when the field is let go (one undo
/// step per edit).
bool mixedNumberField(const char* label, const std::optional<double>& shared, double& value, bool& released,
                      const char* format = "%.3f");

/// A drop-down of names for a multi-selection: shows the shared name, or "mixed"; true when one is picked into name.
bool mixedNameCombo(const char* label, const std::optional<std::string>& shared, const std::vector<std::string>& names,
                    std::string& name);

} // namespace abalike::app

#include "level/JsonLocator.hpp"
#include "level/JsonText.hpp"
#include "level/LevelReader.hpp"

#include <abalike/level/LevelNumbering.hpp>

#include <set>

namespace abalike
{

namespace
{

/// The step at `pointer`, whose numbering must be `expected`; problems go to the reader.
Renumbering readStep(LevelReader& r, const nlohmann::json& step, const std::string& pointer, int expected)
{
    Renumbering out;
    if (!r.object(step, pointer, {"numbering", "ids"}))
        return out;
    out.numbering = static_cast<int>(r.number(step, pointer, "numbering", expected, true, 2, 1000));
    if (out.numbering != expected)
        r.error(pointer + "/numbering", "numbering " + std::to_string(out.numbering) + " follows numbering " +
                                            std::to_string(expected - 1) + " (expected " + std::to_string(expected) +
                                            ": each renumbering adds one)");
    const auto ids = step.find("ids");
    if (ids == step.end())
    {
        r.error(pointer, "missing required key \"ids\" (expected an object of old level id -> new level id)");
        return out;
    }
    if (!ids->is_object())
    {
        r.error(pointer + "/ids", "expected an object of old level id -> new level id, got " + describeJsonType(*ids));
        return out;
    }
    std::set<std::string> newIds;
    for (const auto& [oldId, newId] : ids->items())
    {
        const std::string at = pointer + "/ids/" + oldId;
        if (!newId.is_string() || newId.get<std::string>().empty() || oldId.empty())
        {
            r.error(at, "expected a level id renamed to a non-empty new id, got " + describeJsonType(newId));
            continue;
        }
        if (!newIds.insert(newId.get<std::string>()).second)
        {
            r.error(at, "two levels renamed to \"" + newId.get<std::string>() + "\" (expected each new id once)");
            continue;
        }
        out.newIds[oldId] = newId.get<std::string>();
    }
    return out;
}

} // namespace

std::string LevelNumbering::idNow(const std::string& id, int since) const
{
    std::string now = id;
    for (const Renumbering& step : steps)
        if (step.numbering > since)
            if (const auto renamed = step.newIds.find(now); renamed != step.newIds.end())
                now = renamed->second;
    return now;
}

LevelNumbering loadLevelNumbering(const std::string& manifestPath)
{
    const std::string text = readJsonFile(manifestPath, kManifestText);
    const nlohmann::json root = parseJsonText(text, manifestPath, kManifestText);
    const JsonLocator locator(text);
    LevelReader r(manifestPath, locator);
    LevelNumbering numbering;
    const auto history = root.is_object() ? root.find("renumbered") : root.end();
    if (history == root.end())
        return numbering;
    if (r.array(*history, "/renumbered", 1, 1000, "renumberings"))
        for (std::size_t i = 0; i < history->size(); ++i)
            numbering.steps.push_back(
                readStep(r, (*history)[i], "/renumbered/" + std::to_string(i), static_cast<int>(i) + 2));
    if (!r.ok())
        throw LevelLoadError(r.take());
    return numbering;
}

} // namespace abalike

#include "level/JsonLocator.hpp"
#include "level/JsonText.hpp"
#include "level/LevelReader.hpp"

#include <abalike/script/InputScript.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace abalike
{

namespace
{

using json = nlohmann::json;

/// A script drives a run of at most a few minutes; this keeps a typo like 1e9 from meaning "wait forever".
constexpr int kMaxFrame = 1'000'000;
constexpr std::size_t kMaxEvents = 100'000;
constexpr std::size_t kMaxTextBytes = 4096;

/// Every key an event may have; which of them belong together depends on its kind.
constexpr std::initializer_list<const char*> kEventKeys{"frame", "key",    "action", "shift", "ctrl",  "alt",
                                                        "mouse", "button", "x",      "y",     "wheel", "text"};

/// Reads one event, reporting every problem through the reader.
class EventReader
{
public:
    EventReader(LevelReader& reader, const InputScriptRules& rules) : m_reader(reader), m_rules(rules) {}

    std::optional<ScriptEvent> read(const json& value, const std::string& pointer)
    {
        if (!m_reader.object(value, pointer, kEventKeys))
            return std::nullopt;
        ScriptEvent event;
        event.pointer = pointer;
        const std::size_t issuesBefore = m_reader.issueCount();
        event.frame = wholeNumber(value, pointer, "frame", 1, kMaxFrame, true).value_or(1);

        const int kinds = static_cast<int>(value.contains("key")) + static_cast<int>(value.contains("mouse")) +
                          static_cast<int>(value.contains("wheel")) + static_cast<int>(value.contains("text"));
        if (kinds != 1)
        {
            m_reader.error(pointer, kinds == 0 ? "an event needs one of \"key\", \"mouse\", \"wheel\" or \"text\""
                                               : "an event has exactly one of \"key\", \"mouse\", \"wheel\" or "
                                                 "\"text\" (split it into several events)");
            return std::nullopt;
        }
        if (value.contains("key"))
            readKey(value, pointer, event);
        else if (value.contains("mouse"))
            readMouse(value, pointer, event);
        else if (value.contains("wheel"))
            readWheel(value, pointer, event);
        else
            readText(value, pointer, event);
        return m_reader.issueCount() == issuesBefore ? std::optional<ScriptEvent>(event) : std::nullopt;
    }

private:
    /// A whole number in [min, max]; `context` follows the range in messages, e.g. " (the window is 1280 wide)".
    std::optional<int> wholeNumber(const json& object, const std::string& pointer, const char* key, int min, int max,
                                   bool required, const std::string& context = "")
    {
        const auto it = object.find(key);
        if (it == object.end())
        {
            if (required)
                m_reader.error(pointer, std::string("missing required key \"") + key + "\" (expected a whole number)");
            return std::nullopt;
        }
        const std::string where = pointer + "/" + key;
        const std::string expected =
            "expected a whole number from " + std::to_string(min) + " to " + std::to_string(max) + context;
        if (!it->is_number())
        {
            m_reader.error(where, expected + ", got " + describeJsonType(*it));
            return std::nullopt;
        }
        const double number = it->get<double>();
        if (!std::isfinite(number) || number != std::floor(number) || number < min || number > max)
        {
            m_reader.error(where, expected + ", got " + it->dump());
            return std::nullopt;
        }
        return static_cast<int>(number);
    }

    bool flag(const json& object, const std::string& pointer, const char* key)
    {
        const auto it = object.find(key);
        if (it == object.end())
            return false;
        if (!it->is_boolean())
        {
            m_reader.error(pointer + "/" + key, "expected true or false, got " + describeJsonType(*it));
            return false;
        }
        return it->get<bool>();
    }

    std::optional<std::string> choice(const json& object, const std::string& pointer, const char* key,
                                      const std::vector<std::string>& allowed, const std::string& fallback)
    {
        const auto it = object.find(key);
        if (it == object.end())
        {
            if (fallback.empty())
            {
                m_reader.error(pointer,
                               std::string("missing required key \"") + key + "\" (expected " + listed(allowed) + ")");
                return std::nullopt;
            }
            return fallback;
        }
        const std::string where = pointer + "/" + key;
        if (!it->is_string() || std::find(allowed.begin(), allowed.end(), it->get<std::string>()) == allowed.end())
        {
            m_reader.error(where, "expected " + listed(allowed) + ", got " + describeJsonType(*it));
            return std::nullopt;
        }
        return it->get<std::string>();
    }

    static std::string listed(const std::vector<std::string>& names)
    {
        std::string text;
        for (std::size_t i = 0; i < names.size(); ++i)
            text += (i == 0 ? "\"" : i + 1 == names.size() ? " or \"" : ", \"") + names[i] + "\"";
        return text;
    }

    /// Only keys that belong to the event's kind (unknown keys were reported already).
    void onlyKeys(const json& value, const std::string& pointer, const char* kind,
                  std::initializer_list<const char*> allowed)
    {
        for (auto it = value.begin(); it != value.end(); ++it)
        {
            // Not a structured binding: clang 14 cannot capture one in a lambda.
            const std::string& key = it.key();
            const auto named = [&key](const char* a)
            {
                return key == a;
            };
            if (key == "frame" || std::find_if(allowed.begin(), allowed.end(), named) != allowed.end() ||
                std::find_if(kEventKeys.begin(), kEventKeys.end(), named) == kEventKeys.end())
                continue;
            m_reader.keyError(pointer + "/" + key, "\"" + key + "\" does not belong to a " + kind + " event");
        }
    }

    void readKey(const json& value, const std::string& pointer, ScriptEvent& event)
    {
        event.kind = ScriptEvent::Kind::Key;
        onlyKeys(value, pointer, "key", {"key", "action", "shift", "ctrl", "alt"});
        const json& key = value.at("key");
        if (!key.is_string())
            m_reader.error(pointer + "/key", "expected a key name such as \"Space\", got " + describeJsonType(key));
        else if (!m_rules.isKeyName || !m_rules.isKeyName(key.get<std::string>()))
        {
            std::string message = "unknown key name \"" + key.get<std::string>() + "\"";
            if (const auto suggestion = closestMatch(key.get<std::string>(), m_rules.keyNames))
                message += " (did you mean \"" + *suggestion + "\"?)";
            else
                message += " (expected a key name such as \"Escape\", \"Space\", \"A\", \"Num1\", \"F1\", \"Left\", "
                           "\"Add\")";
            m_reader.error(pointer + "/key", message);
        }
        else
            event.key = key.get<std::string>();
        const std::optional<std::string> action = choice(value, pointer, "action", {"tap", "press", "release"}, "tap");
        event.action = action == "press"     ? ScriptEvent::Action::Press
                       : action == "release" ? ScriptEvent::Action::Release
                                             : ScriptEvent::Action::Tap;
        event.shift = flag(value, pointer, "shift");
        event.ctrl = flag(value, pointer, "ctrl");
        event.alt = flag(value, pointer, "alt");
    }

    void readPosition(const json& value, const std::string& pointer, ScriptEvent& event)
    {
        const std::string window = " (window pixels of the " + std::to_string(m_rules.width) + "x" +
                                   std::to_string(m_rules.height) + " window)";
        event.x = wholeNumber(value, pointer, "x", 0, static_cast<int>(m_rules.width) - 1, true, window).value_or(0);
        event.y = wholeNumber(value, pointer, "y", 0, static_cast<int>(m_rules.height) - 1, true, window).value_or(0);
    }

    void readMouse(const json& value, const std::string& pointer, ScriptEvent& event)
    {
        event.kind = ScriptEvent::Kind::Mouse;
        // Modifiers are keys of their own: hold "LShift" with {"key": "LShift", "action": "press"}.
        onlyKeys(value, pointer, "mouse", {"mouse", "button", "x", "y"});
        const std::optional<std::string> action = choice(value, pointer, "mouse", {"press", "release", "move"}, "");
        event.action = action == "press"     ? ScriptEvent::Action::Press
                       : action == "release" ? ScriptEvent::Action::Release
                                             : ScriptEvent::Action::Move;
        if (action && *action != "move")
            event.button = choice(value, pointer, "button", {"left", "right", "middle"}, "left").value_or("left");
        else if (value.contains("button"))
            m_reader.keyError(pointer + "/button", "a pointer move has no button");
        readPosition(value, pointer, event);
    }

    void readWheel(const json& value, const std::string& pointer, ScriptEvent& event)
    {
        event.kind = ScriptEvent::Kind::Wheel;
        onlyKeys(value, pointer, "wheel", {"wheel", "x", "y"});
        event.wheelDelta = wholeNumber(value, pointer, "wheel", -100, 100, true).value_or(0);
        if (event.wheelDelta == 0 && value.at("wheel").is_number())
            m_reader.error(pointer + "/wheel", "a wheel event turns the wheel (expected a non-zero whole number)");
        readPosition(value, pointer, event);
    }

    void readText(const json& value, const std::string& pointer, ScriptEvent& event)
    {
        event.kind = ScriptEvent::Kind::Text;
        onlyKeys(value, pointer, "text", {"text"});
        const json& text = value.at("text");
        if (!text.is_string() || text.get<std::string>().empty())
            m_reader.error(pointer + "/text", "expected a non-empty string, got " + describeJsonType(text));
        else if (text.get<std::string>().size() > kMaxTextBytes)
            m_reader.error(pointer + "/text",
                           "text too long (expected at most " + std::to_string(kMaxTextBytes) + " bytes)");
        else
            event.text = text.get<std::string>();
    }

    LevelReader& m_reader;
    const InputScriptRules& m_rules;
};

} // namespace

InputScript parseInputScript(std::string_view text, const std::string& fileName, const InputScriptRules& rules)
{
    JsonTextLimits limits;
    limits.what = "an input script";
    const json root = parseJsonText(text, fileName, limits);
    const JsonLocator locator(text);
    LevelReader reader(fileName, locator);
    reader.duplicateKeys();

    InputScript script;
    if (reader.array(root, "", 0, kMaxEvents, "events"))
    {
        EventReader events(reader, rules);
        for (std::size_t i = 0; i < root.size(); ++i)
        {
            // Appended rather than "/" + to_string(i): GCC 12 warns falsely (-Wrestrict) on that expression.
            std::string pointer = "/";
            pointer += std::to_string(i);
            if (std::optional<ScriptEvent> event = events.read(root[i], pointer))
                script.events.push_back(std::move(*event));
        }
    }
    if (std::vector<LevelIssue> issues = reader.take(); !issues.empty())
        throw LevelLoadError(std::move(issues));
    // Events of one frame keep their order in the file.
    std::stable_sort(script.events.begin(), script.events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return script;
}

InputScript loadInputScript(const std::string& path, const InputScriptRules& rules)
{
    JsonTextLimits limits;
    limits.what = "an input script";
    return parseInputScript(readJsonFile(path, limits), path, rules);
}

} // namespace abalike

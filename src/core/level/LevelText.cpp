#include "level/JsonLocator.hpp"
#include <cctype>

#include <abalike/level/LevelText.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike
{

void locateIssues(std::vector<LevelIssue>& issues, std::string_view text, const std::string& file)
{
    const JsonLocator locator(text);
    for (LevelIssue& issue : issues)
    {
        issue.file = file;
        const auto [line, column] = locator.locate(issue.pointer);
        issue.line = line;
        issue.column = column;
    }
}

std::string replaceNumber(std::string_view text, const std::string& pointer, const std::string& number)
{
    const JsonLocator locator(text);
    const std::string_view raw = locator.rawScalar(pointer);
    const bool isNumber = !raw.empty() && (raw.front() == '-' || (raw.front() >= '0' && raw.front() <= '9'));
    if (!isNumber)
        throw std::invalid_argument(pointer + " is not a number in the file");
    const auto offset = static_cast<std::size_t>(raw.data() - text.data());
    std::string out(text.substr(0, offset));
    out += number;
    out += text.substr(offset + raw.size());
    return out;
}

std::string withStars(std::string_view text, const std::array<int, 3>& stars)
{
    const JsonLocator locator(text);
    std::string out(text);
    const std::string_view last = locator.rawScalar("/stars/2");
    if (!last.empty() && last.front() >= '0' && last.front() <= '9')
    {
        for (std::size_t i = 0; i < 3; ++i)
            out = replaceNumber(out, "/stars/" + std::to_string(i), std::to_string(stars[i]));
        return out;
    }
    const std::size_t close = out.find_last_of('}');
    if (close == std::string::npos)
        throw std::invalid_argument("the level file has no closing brace");
    std::size_t end = close;
    while (end > 0 && std::isspace(static_cast<unsigned char>(out[end - 1])))
        --end;
    return out.substr(0, end) + ",\n  \"stars\": [" + std::to_string(stars[0]) + ", " + std::to_string(stars[1]) +
           ", " + std::to_string(stars[2]) + "]\n" + out.substr(close);
}

std::string schemaReferenceOf(std::string_view text)
{
    const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
    if (root.is_object() && root.contains("$schema") && root["$schema"].is_string())
        return root["$schema"].get<std::string>();
    return {};
}

} // namespace abalike

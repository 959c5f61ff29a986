#include "level/JsonLocator.hpp"

#include <abalike/level/LevelText.hpp>
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

} // namespace abalike

#include <abalike/edit/Autosave.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/save/AtomicWrite.hpp>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace abalike
{

namespace
{
constexpr const char* kFileName = "editor-autosave.json";
/// An autosave is a level and a path; anything much larger is not one.
constexpr std::uintmax_t kMaxAutosaveBytes = 8u << 20;
} // namespace

std::filesystem::path autosavePath(const std::filesystem::path& dataDirectory)
{
    return dataDirectory / kFileName;
}

void writeAutosave(const std::filesystem::path& file, const LevelDef& level, const std::filesystem::path& target,
                   const Catalog& catalog)
{
    LevelDef kept = level;
    if (kept.pigs.empty() && !checkLevelFields(kept, catalog).empty())
        kept.sandbox = true;
    const std::string levelText = writeLevelJson(kept, "schema/level.schema.json");
    std::string text = "{\n\"format\": 1,\n\"target\": ";
    text += nlohmann::json(target.string()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    text += ",\n\"level\": " + levelText + "}\n";
    writeFileAtomically(file, text);
}

std::optional<AutosavedScene> readAutosave(const std::filesystem::path& file, const Catalog& catalog)
{
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        return std::nullopt;
    const auto damaged = [&](const std::string& why)
    {
        return LevelLoadError({LevelIssue{file.string(), 0, 0, "", "damaged editor autosave (" + why + ")"}});
    };
    if (std::filesystem::file_size(file, ec) > kMaxAutosaveBytes)
        throw damaged("too large");
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const nlohmann::json root = nlohmann::json::parse(buffer.str(), nullptr, false);
    if (!root.is_object() || !root.contains("level") || !root.contains("target") || !root["target"].is_string())
        throw damaged("expected {\"format\", \"target\", \"level\"}");
    AutosavedScene scene;
    scene.target = root["target"].get<std::string>();
    EditableLevel level = parseLevelForEditing(root["level"].dump(), file.string(), catalog);
    scene.level = std::move(level.level);
    scene.level.sourcePath = scene.target.string();
    scene.geometryIssues = std::move(level.geometryIssues);
    return scene;
}

void removeAutosave(const std::filesystem::path& file)
{
    std::error_code ec;
    std::filesystem::remove(file, ec);
}

} // namespace abalike

#include "cli/GeneratedLevelFile.hpp"

#include "cli/UsageError.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Generator.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <iostream>

namespace abalike::app
{

GeneratedLevelName parseGeneratedLevelName(const std::string& text)
{
    const auto fail = [&text]()
    {
        return UsageError("--generated: expected SEED or SEED:LOSS_SHARE (e.g. 4711 or 4711:0.3), got \"" + text +
                          "\"");
    };
    GeneratedLevelName name;
    const std::size_t colon = text.find(':');
    const std::string seed = text.substr(0, colon);
    if (seed.empty() || seed.find_first_not_of("0123456789") != std::string::npos || seed.size() > 18)
        throw fail();
    name.seed = std::stoull(seed);
    if (colon != std::string::npos)
    {
        std::size_t used = 0;
        try
        {
            name.lossShare = std::stod(text.substr(colon + 1), &used);
        }
        catch (const std::exception&)
        {
            throw fail();
        }
        if (used != text.size() - colon - 1 || !(name.lossShare >= 0.0 && name.lossShare <= 1.0))
            throw fail();
    }
    return name;
}

std::filesystem::path generatedLevelFile(const GeneratedLevelName& name)
{
    const std::string fileName = std::to_string(name.seed) + "-" + shortestNumber(name.lossShare) + ".json";
    const std::filesystem::path levels(levelsDirectory());
    // The endless mode's shipped levels are generated levels too, by the same names.
    if (const std::filesystem::path shipped = levels / "endless" / fileName; std::filesystem::exists(shipped))
        return shipped;
    const std::filesystem::path file = defaultCacheDirectory() / "generated" / fileName;
    if (std::filesystem::exists(file))
        return file;
    std::cerr << "abalike: generating level " << name.seed << " (loss share " << shortestNumber(name.lossShare)
              << "): building and verifying it takes about half a minute; it is kept in " << file.string() << '\n';
    GeneratorOptions options;
    options.seed = name.seed;
    options.lossShare = name.lossShare;
    const GeneratedLevel level =
        generateLevel(loadGeneratorParts((levels / "parts").string(), Catalog::builtin()), options, Catalog::builtin());
    if (!level.ok)
        throw UsageError("--generated " + std::to_string(name.seed) +
                         ": no level passed for this seed and loss share "
                         "in " +
                         std::to_string(level.attempts) + " attempts; try another");
    std::filesystem::create_directories(file.parent_path());
    saveLevel(level.level, file, levels / "schema" / "level.schema.json");
    return file;
}

} // namespace abalike::app

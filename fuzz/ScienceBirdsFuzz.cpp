#include "FuzzInput.hpp"

#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/ScienceBirds.hpp>
#include <abalike/world/Catalog.hpp>

/// The Science Birds import must answer any bytes with a level or a LevelLoadError with at least one issue, and a
/// level it makes must write as a file that reads back as the same level.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace abalike;
    ScienceBirdsLevel imported;
    try
    {
        imported = importScienceBirds(fuzz::asText(data, size), "fuzz.xml", Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        if (e.issues().empty())
            fuzz::fail("LevelLoadError without an issue");
        return 0;
    }
    try
    {
        const EditableLevel reread =
            parseLevelForEditing(writeLevelJson(imported.level, ""), "fuzz.json", Catalog::builtin());
        LevelDef expected = imported.level;
        expected.sourcePath = reread.level.sourcePath;
        if (!(reread.level == expected))
            fuzz::fail("an imported level read back differently");
    }
    catch (const LevelLoadError&)
    {
        fuzz::fail("an imported level does not load");
    }
    return 0;
}

// Bird, ability and material facts in the docs come from the catalog: a table or line between
// `<!-- catalog:NAME -->` and `<!-- /catalog:NAME -->` is catalogDocSection(NAME), a number between `<!--{EXPR}-->`
// and `<!--/-->` is the level texts' placeholder EXPR filled for the default level (docs/materials.md lists the
// values), and one between `<!--[/json/pointer]-->` and `<!--/-->` is that number of assets/catalog.json. A bird's
// mass or a material's strength written by hand beside its name is checked against the catalog. With
// ABALIKE_UPDATE_DOCS=1 the test writes every generated part instead of comparing it. A marker right after a
// backtick is an example in code, left alone.
#include <abalike/teach/TextValues.hpp>
#include <abalike/world/CatalogTable.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

namespace abalike
{
namespace
{

namespace fs = std::filesystem;

/// The docs people read by hand: README.md, docs/*.md and levels/README.md (docs/materials.md is generated whole
/// and docs/teachers.md by tools/teachers-guide; both are checked by their own tests).
std::vector<fs::path> handWrittenDocs()
{
    const fs::path root(ABALIKE_SOURCE_DIR);
    std::vector<fs::path> docs{root / "README.md", root / "levels" / "README.md"};
    for (const auto& entry : fs::directory_iterator(root / "docs"))
        if (entry.path().extension() == ".md" && entry.path().filename() != "materials.md" &&
            entry.path().filename() != "teachers.md")
            docs.push_back(entry.path());
    std::sort(docs.begin(), docs.end());
    return docs;
}

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::size_t lineOf(const std::string& text, std::size_t offset)
{
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

/// A catalog number as the docs write it: as few decimals as it needs, at most three.
std::string shortest(double value)
{
    char out[32];
    std::snprintf(out, sizeof out, "%.3f", value);
    std::string text(out);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.')
        text.pop_back();
    return text;
}

const std::regex& markers()
{
    static const std::regex pattern(R"(<!-- catalog:([a-z-]+) -->([\s\S]*?)<!-- /catalog:\1 -->)"
                                    R"(|<!--\{([^}]*)\}-->([^<]*)<!--/-->)"
                                    R"(|<!--\[([^\]]*)\]-->([^<]*)<!--/-->)");
    return pattern;
}

/// The doc's text with every generated part as the catalog says it, and what was wrong, one line each.
std::string regenerate(const fs::path& path, const std::string& text, std::string& problems)
{
    static const nlohmann::json catalogJson = nlohmann::json::parse(Catalog::builtinJson());
    std::string out;
    std::size_t last = 0;
    for (std::sregex_iterator it(text.begin(), text.end(), markers()), end; it != end; ++it)
    {
        // One alternative per kind of marker: a section (1, 2), a placeholder (3, 4), a catalog number (5, 6).
        const std::smatch& m = *it;
        // A marker right after a backtick is an example written in code (docs/extending.md), not a marker.
        if (m.position() > 0 && text[static_cast<std::size_t>(m.position()) - 1] == '`')
            continue;
        std::string want;
        std::string have;
        std::string opening;
        std::string closing;
        if (m[1].matched)
        {
            const auto section = catalogDocSection(Catalog::builtin(), m[1].str());
            have = m[2].str();
            // A table stands on lines of its own; a line's part is inline.
            want = !section                 ? "!no catalog section \"" + m[1].str() + "\""
                   : have.starts_with('\n') ? "\n" + *section
                                            : *section;
            opening = "<!-- catalog:" + m[1].str() + " -->";
            closing = "<!-- /catalog:" + m[1].str() + " -->";
        }
        else
        {
            const bool placeholder = m[3].matched;
            const std::string key = placeholder ? m[3].str() : m[5].str();
            have = placeholder ? m[4].str() : m[6].str();
            opening = placeholder ? "<!--{" + key + "}-->" : "<!--[" + key + "]-->";
            closing = "<!--/-->";
            if (placeholder)
            {
                try
                {
                    want = fillText("{" + key + "}", LevelDef{}, Catalog::builtin());
                }
                catch (const std::exception& e)
                {
                    want = "!placeholder {" + key + "}: " + e.what();
                }
            }
            else
            {
                const nlohmann::json::json_pointer pointer(key);
                want = catalogJson.contains(pointer) && catalogJson.at(pointer).is_number()
                           ? shortest(catalogJson.at(pointer).get<double>())
                           : "!assets/catalog.json has no number at " + key;
            }
        }
        const std::size_t line = lineOf(text, static_cast<std::size_t>(m.position()));
        if (want.starts_with('!'))
        {
            problems += path.string() + ":" + std::to_string(line) + ": " + want.substr(1) + "\n";
            want = have;
        }
        else if (want != have)
            problems += path.string() + ":" + std::to_string(line) + ": " + opening + " says \"" + have.substr(0, 60) +
                        "\", the catalog \"" + want.substr(0, 60) + "\"\n";
        out += text.substr(last, static_cast<std::size_t>(m.position()) - last) + opening + want + closing;
        last = static_cast<std::size_t>(m.position() + m.length());
    }
    return out + text.substr(last);
}

TEST(CatalogDocs, GeneratedPartsOfTheDocsMatchTheCatalog)
{
    const bool update = std::getenv("ABALIKE_UPDATE_DOCS") != nullptr;
    std::string problems;
    std::size_t parts = 0;
    for (const fs::path& path : handWrittenDocs())
    {
        const std::string text = readFile(path);
        parts += static_cast<std::size_t>(
            std::distance(std::sregex_iterator(text.begin(), text.end(), markers()), std::sregex_iterator()));
        std::string found;
        const std::string fixed = regenerate(path, text, found);
        if (update && fixed != text)
            std::ofstream(path, std::ios::binary) << fixed;
        problems += found;
    }
    // The five docs the bird facts used to be copied into by hand embed them now (README, playing, slingshot,
    // world-physics, levels/README): a doc that drops its markers is caught here.
    EXPECT_GE(parts, 20u);
    if (update)
        GTEST_SKIP() << "regenerated the docs' catalog parts";
    EXPECT_EQ(problems, "") << "run with ABALIKE_UPDATE_DOCS=1 to regenerate";
}

/// Outside the generated parts, what a doc writes by hand beside a bird's or a material's name must agree with the
/// catalog: "the black bird (8 kg)", "red, 4 kg", "stone (300 N·s)".
TEST(CatalogDocs, HandWrittenMassesAndStrengthsAgreeWithTheCatalog)
{
    const Catalog& catalog = Catalog::builtin();
    std::string problems;
    std::size_t checked = 0;
    for (const fs::path& path : handWrittenDocs())
    {
        std::string text = readFile(path);
        // Blank the generated parts (keeping the offsets) so only hand-written text is checked.
        for (std::sregex_iterator it(text.begin(), text.end(), markers()), end; it != end; ++it)
            std::fill_n(text.begin() + it->position(), it->length(), ' ');
        for (const BirdType& bird : catalog.birds())
        {
            const std::regex mass("\\b" + bird.name +
                                  "\\b(?: bird| one)?(?:,| \\(| at| of)? ?([0-9]+(?:\\.[0-9]+)?) kg");
            for (std::sregex_iterator it(text.begin(), text.end(), mass), end; it != end; ++it, ++checked)
                if (std::abs(std::stod((*it)[1].str()) - bird.massKg) > 1e-9)
                    problems += path.string() + ":" + std::to_string(lineOf(text, it->position())) + ": \"" +
                                it->str() + "\": the catalog's " + bird.name + " bird is " + shortest(bird.massKg) +
                                " kg\n";
        }
        for (const Material& material : catalog.materials())
        {
            const std::regex strength("\\b" + material.name + "\\b(?: block)?(?: \\(| takes | )([0-9]+) N(?:·| )s");
            for (std::sregex_iterator it(text.begin(), text.end(), strength), end; it != end; ++it, ++checked)
                if (std::abs(std::stod((*it)[1].str()) - material.strengthNs) > 1e-9)
                    problems += path.string() + ":" + std::to_string(lineOf(text, it->position())) + ": \"" +
                                it->str() + "\": the catalog's " + material.name + " takes " +
                                shortest(material.strengthNs) + " N·s\n";
        }
    }
    EXPECT_GT(checked, 0u) << "the patterns no longer find what the docs write";
    EXPECT_EQ(problems, "");
}

TEST(CatalogDocs, EverySectionNameRenders)
{
    for (const std::string_view name : catalogDocSectionNames())
    {
        const auto section = catalogDocSection(Catalog::builtin(), name);
        ASSERT_TRUE(section) << name;
        EXPECT_FALSE(section->empty()) << name;
    }
    EXPECT_FALSE(catalogDocSection(Catalog::builtin(), "no-such-section"));
}

} // namespace
} // namespace abalike

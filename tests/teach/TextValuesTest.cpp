#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/TextValues.hpp>
#include <abalike/world/Catalog.hpp>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace abalike;

namespace
{

std::vector<std::filesystem::path> bundledLevelFiles()
{
    std::vector<std::filesystem::path> files;
    const std::filesystem::path root = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels";
    for (const char* folder : {"", "lessons", "structures"})
        for (const auto& entry : std::filesystem::directory_iterator(root / folder))
            if (entry.path().extension() == ".json" && entry.path().filename() != "campaign.json")
                files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// The text with every {...} placeholder cut out: what the author typed.
std::string typedPart(const std::string& text)
{
    std::string out;
    int depth = 0;
    for (char c : text)
    {
        if (c == '{')
            ++depth;
        else if (c == '}')
            depth = std::max(0, depth - 1);
        else if (depth == 0)
            out += c;
    }
    return out;
}

/// Numbers a text may type because they are mathematics, not the game's physics: the 1/2, 2 and 90 of formulas,
/// and the angles of the vacuum range rule (45 is the best from the ground; 30 and 60 share a range).
const std::set<std::string> kMathNumbers{"1", "2", "30", "45", "60", "90"};
/// Number words hide numbers from a digit check.
const std::regex kNumberWord(
    R"(\b(half|twice|double|triple|three|four|five|six|seven|eight|nine|ten|third|quarter|fifth|sixth|sixtieth)\b)",
    std::regex::icase);

LevelDef levelWithTexts(const std::string& json)
{
    const std::string slingshot =
        json.find("\"slingshot\"") == std::string::npos ? R"(, "slingshot": {"x": 0, "y": 1.5})" : "";
    return parseLevel(R"({"format": 1, "id": "t", "title": "T", "birds": ["red"], "pigs": [{"x": 20, "y": 0.25}])" +
                          slingshot + json + "}",
                      "t.json", Catalog::builtin());
}

} // namespace

TEST(TextValues, EveryBundledTextFillsAndTypesNoPhysicsNumber)
{
    const Catalog& catalog = Catalog::builtin();
    int texts = 0;
    int placeholders = 0;
    for (const std::filesystem::path& file : bundledLevelFiles())
    {
        SCOPED_TRACE(file.string());
        const LevelDef level = loadLevel(file.string(), catalog);
        std::vector<std::string> all{level.lesson};
        all.insert(all.end(), level.hints.begin(), level.hints.end());
        for (const std::string& text : all)
        {
            if (text.empty())
                continue;
            ++texts;
            placeholders += static_cast<int>(std::count(text.begin(), text.end(), '{'));
            std::string filled;
            ASSERT_NO_THROW(filled = fillText(text, level, catalog)) << text;
            EXPECT_EQ(filled.find('{'), std::string::npos) << filled;
            const std::string typed = typedPart(text);
            // A number on its own, not the 0 of v0 or the exponent of m^3.
            static const std::regex number(R"((^|[^A-Za-z0-9_^.])(\d+(\.\d+)?))");
            for (auto it = std::sregex_iterator(typed.begin(), typed.end(), number); it != std::sregex_iterator(); ++it)
                EXPECT_TRUE(kMathNumbers.contains((*it)[2].str()))
                    << "typed number " << (*it)[2].str() << " in \"" << text << "\": fill it from the physics ({...})";
            EXPECT_FALSE(std::regex_search(typed, kNumberWord)) << "a number in words in \"" << text << "\"";
        }
    }
    // The campaign and the lessons teach with numbers: most of them come from placeholders.
    EXPECT_GE(texts, 50);
    EXPECT_GE(placeholders, 70);
}

TEST(TextValues, ValuesAreTheLevelsOwnPhysicsRecomputedFromFirstPrinciples)
{
    const Catalog& catalog = Catalog::builtin();
    const LevelDef level = levelWithTexts(R"(, "slingshot": {"x": 0, "y": 2.5, "max_force_n": 1250, "max_pull_m": 1.6,
        "band_mass_kg": 6}, "environment": {"gravity": 3.71, "air_density": 0.5, "wind": [-3, 4]},
        "materials": {"ice": {"strength_ns": 30, "density_kg_per_m3": 600}}, "time_limit_s": 42)");
    const double energy = 0.5 * 1250.0 * 1.6; // E = 1/2 F x, 1000 J
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "energy", ""), energy);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "force", ""), 1250.0);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "pull", ""), 1.6);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "band_mass", ""), 6.0);
    for (const auto& [bird, mass] :
         std::vector<std::pair<std::string, double>>{{"red", 4.0}, {"blue", 1.5}, {"black", 8.0}})
    {
        const double v = std::sqrt(2.0 * energy / (mass + 6.0)); // 1/2 (m + m_b) v^2 = E
        EXPECT_NEAR(textValue(level, catalog, "v_max", bird), v, 1e-12) << bird;
        EXPECT_NEAR(textValue(level, catalog, "p_max", bird), mass * v, 1e-9) << bird;
        EXPECT_NEAR(textValue(level, catalog, "e_bird", bird), energy * mass / (mass + 6.0), 1e-9) << bird;
        EXPECT_NEAR(textValue(level, catalog, "share", bird), 100.0 * mass / (mass + 6.0), 1e-9) << bird;
        EXPECT_NEAR(textValue(level, catalog, "range_flat", bird), v * v / 3.71, 1e-9) << bird;
        EXPECT_DOUBLE_EQ(textValue(level, catalog, "mass", bird), mass);
    }
    // Terminal speed: m g = 1/2 rho Cd A v^2 with the red bird's Cd 0.47 and radius 0.25 m.
    const double c = 0.5 * 0.5 * 0.47 * M_PI * 0.25 * 0.25;
    EXPECT_NEAR(textValue(level, catalog, "terminal", "red"), std::sqrt(4.0 * 3.71 / c), 1e-9);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "g", ""), 3.71);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "rho", ""), 0.5);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "wind", ""), 5.0);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "launch_height", ""), 2.5);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "time_limit", ""), 42.0);
    // The level's own material values, not the catalog's.
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "strength", "ice"), 30.0);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "density", "ice"), 600.0);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "areal_density", "ice"), 600.0 * catalog.slabDepthM());
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "strength", "wood"), catalog.findMaterial("wood")->strengthNs);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "health", "helmet"), catalog.findPig("helmet")->healthNs);
    // The white bird's egg, as the catalog has it (assets/catalog.json): 10 kg, 15 m/s faster downwards.
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "egg_mass", ""), 10.0);
    EXPECT_DOUBLE_EQ(textValue(level, catalog, "egg_push", ""), 15.0);
}

TEST(TextValues, VacuumBestAngleFromAHeightMatchesTheClosedForm)
{
    // From height h at speed v the farthest angle satisfies tan(theta) = v / sqrt(v^2 + 2 g h), and the range is
    // (v / g) sqrt(v^2 + 2 g h).
    const Catalog& catalog = Catalog::builtin();
    const LevelDef level = levelWithTexts(R"(, "slingshot": {"x": 0, "y": 10.5})");
    const double v = std::sqrt(1800.0 * 2.0 / 4.0);
    const double g = 9.81;
    const double h = 10.5;
    const double angle = std::atan(v / std::sqrt(v * v + 2.0 * g * h)) * 180.0 / M_PI;
    EXPECT_NEAR(textValue(level, catalog, "vacuum_best_angle", "red"), angle, 0.01);
    EXPECT_NEAR(textValue(level, catalog, "vacuum_best_range", "red"), v / g * std::sqrt(v * v + 2.0 * g * h), 0.01);
    // Air shortens the best range and lowers the best angle.
    const LevelDef air = levelWithTexts(R"(, "slingshot": {"x": 0, "y": 10.5}, "environment": {"air_density": 1.2})");
    EXPECT_LT(textValue(air, catalog, "best_range", "red"), textValue(air, catalog, "vacuum_best_range", "red") - 5.0);
    EXPECT_LT(textValue(air, catalog, "best_angle", "red"), angle - 1.0);
}

TEST(TextValues, FillFormatsDecimalsAndExpressions)
{
    const Catalog& catalog = Catalog::builtin();
    const LevelDef level = levelWithTexts(
        R"(, "environment": {"gravity": 1.62, "air_density": 0.01, "gusts": [{"t": 1, "wx": -10, "wy": 0}, {"t": 2.5, "wx": 3, "wy": 0}]})");
    EXPECT_EQ(fillText("red {v_max:red} m/s, {p_max:red} N s, {energy} J", level, catalog),
              "red 17.5 m/s, 70 N s, 2756 J"); // the Moon's band
    EXPECT_EQ(fillText("{earth_g / g|1} times, {v_max:blue / v_max:red|2}", level, catalog), "6.1 times, 1.08");
    EXPECT_EQ(fillText("{-gust_wx:1} then {gust_wx:2} for {gust_t:2 - gust_t:1} s", level, catalog),
              "10 then 3 for 1.50 s");
    EXPECT_EQ(fillText("{sqrt(4) * (1 + 2)|0} {{braces}}", level, catalog), "6 {braces}");
    EXPECT_EQ(fillText("g {g}, rho {rho}", level, catalog), "g 1.62, rho 0.01");
}

TEST(TextValues, ABadPlaceholderIsAReaderErrorThatSaysWhereAndWhat)
{
    const auto errorOf = [](const std::string& conceptText)
    {
        try
        {
            levelWithTexts(R"(, "concept": ")" + conceptText + R"(", "hints": ["fine {v_max:red}"])");
        }
        catch (const LevelLoadError& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(errorOf("{v_mx:red}")
                  .find("/concept: character 2 of the text: unknown value \"v_mx\" (did you mean \"v_max\"?)"),
              std::string::npos)
        << errorOf("{v_mx:red}");
    // Nothing close: every name, so the writer can pick.
    EXPECT_NE(errorOf("{xyzzy}").find("unknown value \"xyzzy\" (known: v_max:BIRD, p_max:BIRD"), std::string::npos)
        << errorOf("{xyzzy}");
    // A bird the catalog cannot have: every bird's name with a suffix, so it is longer than any of them.
    std::string missing = "bird";
    for (const BirdType& bird : Catalog::builtin().birds())
        missing += bird.name;
    ASSERT_EQ(Catalog::builtin().findBird(missing), nullptr);
    EXPECT_NE(errorOf("a {v_max:" + missing + "}").find("no bird named \"" + missing + "\""), std::string::npos);
    EXPECT_NE(errorOf("{v_max}").find("{v_max} needs BIRD, as {v_max:BIRD}"), std::string::npos);
    EXPECT_NE(errorOf("{g:red}").find("{g} takes no argument"), std::string::npos);
    EXPECT_NE(errorOf("{gust_t:1}").find("no gust steps"), std::string::npos);
    // A brace that cannot start a placeholder is text, as it was before placeholders (format 1 stays readable).
    EXPECT_EQ(errorOf("open { here, and {a, b} and }"), "no error");
    EXPECT_NE(errorOf("{g|x}").find("expected 0 to 9 decimals"), std::string::npos);
    EXPECT_NE(errorOf("{g +}").find("expected a value"), std::string::npos);
    EXPECT_NE(errorOf("{time_limit}").find("no time_limit_s"), std::string::npos);
    EXPECT_EQ(errorOf("fine {v_max:red} and {{"), "no error");
}

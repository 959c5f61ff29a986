// `check --fix` over the mistakes a designer makes, at random (issue 56, item 3): 200 cases from a fixed seed, each a
// campaign level with one body moved (floated 2-30 cm, sunk 1-20 cm into what is under it, shifted 5-50 cm sideways,
// or sunk 1-20 cm below the ground), in turn. A case that `check` still passes broke nothing and is not counted; of
// the rest, `--fix` must bring at least 90 % back: passing `check`, and the level's reference shot defeating at least
// as many pigs as on the level as shipped.
#include "../SanitizerBuild.hpp"
#include "RunAbalike.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace abalike::test
{
namespace
{

/// The campaign's level files, in the manifest's order.
std::vector<std::string> campaignLevels()
{
    const nlohmann::json manifest = nlohmann::json::parse(std::ifstream(sourcePath("levels/campaign.json")));
    std::vector<std::string> levels;
    for (const nlohmann::json& episode : manifest["episodes"])
        for (const nlohmann::json& file : episode["levels"])
            levels.push_back(sourcePath("levels/" + file.get<std::string>()));
    return levels;
}

/// Uniform numbers from the 32-bit engine alone (the standard library's distributions differ between libraries).
class CaseRandom
{
public:
    explicit CaseRandom(std::uint32_t seed) : m_engine(seed) {}
    double uniform(double low, double high) { return low + (high - low) * (m_engine() >> 8) / double(1u << 24); }
    std::size_t index(std::size_t count) { return m_engine() % count; }
    double sign() { return (m_engine() & 1u) != 0u ? 1.0 : -1.0; }

private:
    std::mt19937 m_engine;
};

double millimetres(double metres)
{
    return std::round(metres * 1000.0) / 1000.0;
}

enum class Mistake
{
    Float,
    Overlap,
    Shift,
    SinkBelowGround
};

const char* nameOf(Mistake mistake)
{
    switch (mistake)
    {
    case Mistake::Float:
        return "float 2-30 cm";
    case Mistake::Overlap:
        return "overlap 1-20 cm";
    case Mistake::Shift:
        return "shift 5-50 cm";
    case Mistake::SinkBelowGround:
        return "sink below the ground";
    }
    return "";
}

/// Makes the mistake on one body of the level; false when the level has no body it applies to.
bool makeMistake(nlohmann::json& level, Mistake mistake, CaseRandom& random)
{
    std::vector<nlohmann::json*> bodies;
    for (const char* kind : {"blocks", "pigs"})
        if (level.contains(kind))
            for (nlohmann::json& body : level[kind])
                bodies.push_back(&body);
    if (mistake == Mistake::SinkBelowGround)
    {
        // An upright block standing on the ground goes into it.
        const double ground = level.contains("ground") ? level["ground"].value("y", 0.0) : 0.0;
        std::vector<nlohmann::json*> onGround;
        for (nlohmann::json& block : level["blocks"])
            if (block.value("angle_deg", 0.0) == 0.0 && block.contains("h") &&
                std::abs(block["y"].get<double>() - 0.5 * block["h"].get<double>() - ground) < 0.01)
                onGround.push_back(&block);
        if (onGround.empty())
            return false;
        nlohmann::json& block = *onGround[random.index(onGround.size())];
        block["y"] = millimetres(block["y"].get<double>() - random.uniform(0.01, 0.20));
        return true;
    }
    nlohmann::json& body = *bodies[random.index(bodies.size())];
    if (mistake == Mistake::Float)
        body["y"] = millimetres(body["y"].get<double>() + random.uniform(0.02, 0.30));
    else if (mistake == Mistake::Overlap)
        body["y"] = millimetres(body["y"].get<double>() - random.uniform(0.01, 0.20));
    else
        body["x"] = millimetres(body["x"].get<double>() + random.sign() * random.uniform(0.05, 0.50));
    return true;
}

/// Pigs the level's reference shot defeats; -1 when the run fails.
int pigsDefeated(const std::string& path, const nlohmann::json& level)
{
    std::string shot;
    for (const nlohmann::json& value : level["reference_shot"])
        shot += (shot.empty() ? "" : ",") + value.dump();
    const RunResult run = runAbalike("simulate " + path + " --shot " + shot + " --json");
    if (run.exitCode != 0)
        return -1;
    return static_cast<int>(level["pigs"].size()) - nlohmann::json::parse(run.out)["pigs_remaining"].get<int>();
}

TEST(CheckFixSweep, NineInTenRandomMistakesOnTheCampaignAreFixedAndTheLevelStillPlays)
{
    // The sanitizer build makes the first quarter of the cases (its floating point may settle a case differently).
    const int cases = kSanitizerBuild ? 50 : 200;
    const std::vector<std::string> levels = campaignLevels();
    const auto path =
        std::filesystem::temp_directory_path() / ("abalike-fix-sweep-" + std::to_string(::getpid()) + ".json");
    CaseRandom random(7);
    std::map<std::string, int> shippedDefeats;
    std::map<Mistake, std::pair<int, int>> fixedOfBroken;
    std::vector<std::string> notFixed;
    for (int i = 0; i < cases; ++i)
    {
        const auto mistake = static_cast<Mistake>(i % 4);
        const std::string& shipped = levels[random.index(levels.size())];
        nlohmann::json level = nlohmann::json::parse(std::ifstream(shipped));
        if (!shippedDefeats.count(shipped))
            shippedDefeats[shipped] = pigsDefeated(shipped, level);
        if (!makeMistake(level, mistake, random))
            continue;
        std::ofstream(path) << level.dump(2);
        if (runAbalike("check " + path.string()).exitCode == 0)
            continue; // the move broke nothing
        ++fixedOfBroken[mistake].second;
        const RunResult fix = runAbalike("check --fix " + path.string());
        const RunResult after = runAbalike("check " + path.string());
        const int defeats = after.exitCode == 0 ? pigsDefeated(path.string(), level) : -1;
        if (after.exitCode == 0 && defeats >= shippedDefeats[shipped])
            ++fixedOfBroken[mistake].first;
        else
            notFixed.push_back("case " + std::to_string(i) + " (" + nameOf(mistake) + ", " +
                               std::filesystem::path(shipped).filename().string() + "): " +
                               (after.exitCode != 0
                                    ? after.out.substr(0, 300)
                                    : "the reference shot defeats " + std::to_string(defeats) + " pigs, " +
                                          std::to_string(shippedDefeats[shipped]) + " as shipped"));
    }
    std::filesystem::remove(path);
    int fixed = 0;
    int broken = 0;
    for (const auto& [mistake, counts] : fixedOfBroken)
    {
        std::cout << nameOf(mistake) << ": " << counts.first << " of " << counts.second << " fixed\n";
        fixed += counts.first;
        broken += counts.second;
    }
    std::cout << "in all: " << fixed << " of " << broken << " broken cases fixed\n";
    for (const std::string& line : notFixed)
        std::cout << "  not fixed: " << line << "\n";
    // Most moves break the level (the rest are moves within what check allows, such as a pig nudged along a plank).
    EXPECT_GE(broken, cases * 3 / 4);
    EXPECT_GE(fixed * 10, broken * 9) << fixed << " of " << broken << " broken cases fixed";
    for (const auto& [mistake, counts] : fixedOfBroken)
        EXPECT_GT(counts.first, 0) << nameOf(mistake) << ": none fixed";
}

} // namespace
} // namespace abalike::test

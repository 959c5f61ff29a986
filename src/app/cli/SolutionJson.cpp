#include "cli/SolutionJson.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace abalike::app
{

namespace
{
/// A double as JSON writes it: the shortest text that reads back as the same number.
std::string shortest(double value)
{
    return nlohmann::json(value).dump();
}
} // namespace

nlohmann::ordered_json solutionToJson(const LevelDef& level, const Solution& solution)
{
    nlohmann::ordered_json out;
    out["level"] = level.id;
    out["won"] = solution.outcome.won;
    out["score"] = solution.outcome.score;
    out["stars"] = solution.outcome.stars;
    out["seconds"] = solution.seconds;
    nlohmann::ordered_json shots = nlohmann::ordered_json::array();
    for (const ScriptedShot& shot : solution.shots)
        shots.push_back({{"angle_deg", shot.angleDeg},
                         {"speed", shot.speedMps},
                         {"ability_at_s", shot.abilityAtS ? nlohmann::ordered_json(*shot.abilityAtS) : nullptr}});
    out["shots"] = std::move(shots);
    out["pigs_remaining"] = solution.outcome.pigsRemaining;
    out["simulations"] = solution.simulations;
    out["surviving_pigs"] = solution.survivingPigs;
    out["pigs_falling_alone"] = solution.pigsFallingAlone;
    return out;
}

nlohmann::ordered_json playerDifficultyJson(const PlayerDifficulty& player)
{
    return {{"runs", player.runs},
            {"wins", player.wins},
            {"win_share", player.winShare},
            {"low90", player.low90},
            {"high90", player.high90},
            {"win_scores", player.winScores},
            {"simulations", player.simulations},
            {"seconds", player.seconds}};
}

std::string playerDifficultyText(const PlayerDifficulty& player)
{
    const auto percent = [](double share)
    {
        return std::to_string(static_cast<int>(std::lround(100.0 * share)));
    };
    std::ostringstream text;
    text << "model player: " << player.wins << " of " << player.runs << " runs won (" << percent(player.winShare)
         << " %, 90 % interval " << percent(player.low90) << "-" << percent(player.high90) << " %), "
         << player.simulations << " games in " << std::fixed << std::setprecision(1) << player.seconds << " s";
    return text.str();
}

std::string shotArguments(const std::vector<ScriptedShot>& shots)
{
    std::string out;
    for (const ScriptedShot& shot : shots)
    {
        out += out.empty() ? "--shot " : " --shot ";
        out += shortest(shot.angleDeg);
        out += ',';
        out += shortest(shot.speedMps);
        if (shot.abilityAtS)
        {
            out += ',';
            out += shortest(*shot.abilityAtS);
        }
    }
    return out;
}

} // namespace abalike::app

#include "cli/SolutionJson.hpp"

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

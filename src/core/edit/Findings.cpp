#include <abalike/edit/Findings.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/world/RestFindings.hpp>

#include <regex>
#include <sstream>

namespace abalike
{

std::vector<Finding> findingsFromIssues(const std::vector<LevelIssue>& issues)
{
    std::vector<Finding> out;
    // "overlaps /blocks/2 (...)": the other body of an overlap is named in the message.
    static const std::regex other(R"(overlaps (/(?:blocks|pigs|terrain)/\d+))");
    for (const LevelIssue& issue : issues)
    {
        Finding finding{FindingSource::Geometry, objectOfPointer(issue.pointer), issue.message};
        out.push_back(finding);
        std::smatch match;
        if (std::regex_search(issue.message, match, other))
            if (const auto second = objectOfPointer(match[1].str()))
                out.push_back({FindingSource::Geometry, second, "overlapped by " + issue.pointer});
    }
    return out;
}

std::vector<Finding> findingsFromRest(const LevelDef& level, const Catalog& catalog, const RestReport& report)
{
    // The CLI's findings (restFindings: what is wrong, its verified fix), word for word, on the body each concerns;
    // a body that only follows another is marked too, pointing at the one to fix.
    std::vector<Finding> out;
    if (!report.passed())
        for (const RestFinding& finding : restFindings(level, catalog, report))
        {
            out.push_back({FindingSource::Rest, objectOfPointer(finding.pointer), finding.message()});
            for (const std::string& follower : finding.consequences)
                out.push_back({FindingSource::Rest, objectOfPointer(follower),
                               "moves because " + finding.pointer + " does (fix that one)"});
        }
    if (out.empty())
        out.push_back({FindingSource::Rest, std::nullopt, report.summary()});
    return out;
}

std::vector<Finding> findingsFromSolution(const LevelDef& level, const Solution& solution, const Catalog& catalog)
{
    std::vector<Finding> out;
    std::ostringstream summary;
    if (solution.outcome.won)
        summary << "won with " << solution.shots.size() << " shot(s): " << solution.outcome.score << " points, "
                << solution.outcome.stars << " star(s)";
    else
        summary << "no win found: the best of " << solution.simulations << " sequences leaves "
                << solution.outcome.pigsRemaining << " pig(s) standing";
    out.push_back({FindingSource::Solver, std::nullopt, summary.str()});
    if (solution.outcome.won || level.pigs.empty())
        return out;
    const auto session = simulateShots(level, solution.shots, catalog);
    for (const Entity& entity : session->world().entities())
        if (entity.kind == EntityKind::Pig && entity.alive)
            out.push_back({FindingSource::Solver, ObjectRef{ObjectKind::Pig, static_cast<std::size_t>(entity.defIndex)},
                           "still standing after the solver's best shots"});
    return out;
}

} // namespace abalike

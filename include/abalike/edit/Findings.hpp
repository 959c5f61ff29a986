#pragma once

#include <abalike/design/Solver.hpp>
#include <abalike/edit/SceneObject.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Which check found something.
enum class FindingSource
{
    Geometry, ///< the loader's checks: overlaps, world bounds, reach, the slingshot
    Rest,     ///< the rest test: a body moved or took damage with nothing shot at it
    Solver,   ///< the solver: a pig its best shots leave standing
};

/// Something a check found, on the object it concerns (the editor marks it there) or on the level as a whole.
struct Finding
{
    FindingSource source = FindingSource::Geometry;
    std::optional<ObjectRef> object; ///< none: about the whole level
    std::string message;
};

/// The loader's geometry findings, each on the object its pointer names (an overlap is marked on both bodies).
std::vector<Finding> findingsFromIssues(const std::vector<LevelIssue>& issues);

/// The rest test's findings, in the words `abalike check` prints (what moved and why, the verified fix), each on the
/// body it concerns; bodies that only follow another are marked as such. One level-wide line when it passed.
std::vector<Finding> findingsFromRest(const LevelDef& level, const Catalog& catalog, const RestReport& report);

/// The solver's findings: the pigs its best shot sequence leaves standing (found by playing it again), or one
/// level-wide finding saying what it achieved.
std::vector<Finding> findingsFromSolution(const LevelDef& level, const Solution& solution,
                                          const Catalog& catalog = Catalog::builtin());

} // namespace abalike

#include "editor/EditorChecks.hpp"

#include "shell/Trace.hpp"

#include <abalike/design/Solver.hpp>
#include <abalike/world/RestCheck.hpp>

#include <algorithm>
#include <chrono>

namespace abalike::app
{

namespace
{
/// Above this many bodies the rest test takes long enough to stall the editor; it is then re-run by hand.
constexpr std::size_t kAutoRestBodies = 200;
} // namespace

namespace
{
const char* sourceName(FindingSource source)
{
    switch (source)
    {
    case FindingSource::Geometry:
        return "geometry and reach";
    case FindingSource::Rest:
        return "rest test";
    case FindingSource::Solver:
        break;
    }
    return "solver";
}

std::string countOf(std::size_t n, const char* what)
{
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}
} // namespace

EditorChecks::~EditorChecks()
{
    // The solver works on its own copy of the level; wait for it rather than leave threads running at exit.
    if (m_solver.valid())
        m_solver.wait();
}

void EditorChecks::replace(FindingSource source, std::vector<Finding> findings, std::uint64_t revision,
                           std::string summary)
{
    std::erase_if(m_findings, [source](const Finding& f) { return f.source == source; });
    m_findings.insert(m_findings.end(), findings.begin(), findings.end());
    m_ran[static_cast<int>(source)] = revision;
    const std::string prefix = std::string(sourceName(source)) + ": ";
    std::erase_if(m_summaries, [&](const std::string& s) { return s.rfind(prefix, 0) == 0; });
    m_summaries.push_back(prefix + summary);
}

void EditorChecks::setOpeningIssues(const std::vector<LevelIssue>& issues, std::uint64_t revision)
{
    if (issues.empty())
        return;
    replace(FindingSource::Geometry, findingsFromIssues(issues), revision,
            countOf(issues.size(), "problem") + " when the file was opened");
}

void EditorChecks::runGeometry(const LevelDef& level, std::uint64_t revision)
{
    const auto issues = checkLevelGeometry(level, Catalog::builtin());
    replace(FindingSource::Geometry, findingsFromIssues(issues), revision,
            issues.empty() ? "no problem" : countOf(issues.size(), "problem"));
}

void EditorChecks::runRest(const LevelDef& level, std::uint64_t revision)
{
    const RestReport report = checkRest(level);
    std::vector<Finding> findings = findingsFromRest(level, Catalog::builtin(), report);
    // A passing test leaves one level-wide line; keep it in the summary, not as a marker.
    std::erase_if(findings, [](const Finding& f) { return !f.object; });
    replace(FindingSource::Rest, std::move(findings), revision, report.summary());
}

void EditorChecks::refreshRest(const LevelDef& level, std::uint64_t revision)
{
    if (ranOn(FindingSource::Rest) != revision && level.blocks.size() + level.pigs.size() <= kAutoRestBodies)
        runRest(level, revision);
}

void EditorChecks::startSolver(const LevelDef& level, std::uint64_t revision)
{
    if (m_solver.valid())
        return;
    m_solverRevision = revision;
    m_progress->done = 0;
    m_progress->total = 1;
    auto progress = m_progress;
    m_solver = std::async(std::launch::async,
                          [level, progress]
                          {
                              SolverOptions options;
                              options.progress = [progress](std::size_t done, std::size_t total)
                              {
                                  progress->done = done;
                                  progress->total = std::max<std::size_t>(total, 1);
                              };
                              const Solution solution = solveLevel(level, Catalog::builtin(), options);
                              return findingsFromSolution(level, solution);
                          });
}

void EditorChecks::poll()
{
    if (!m_solver.valid() || m_solver.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    std::vector<Finding> findings;
    std::string summary;
    try
    {
        findings = m_solver.get();
        summary = findings.empty() ? "done" : findings.front().message;
    }
    catch (const std::exception& error)
    {
        summary = std::string("could not run: ") + error.what();
    }
    std::erase_if(findings, [](const Finding& f) { return !f.object; });
    replace(FindingSource::Solver, std::move(findings), m_solverRevision, summary);
}

float EditorChecks::solverProgress() const
{
    return static_cast<float>(m_progress->done) / static_cast<float>(m_progress->total);
}

std::vector<const Finding*> EditorChecks::findingsOn(const ObjectRef& ref) const
{
    std::vector<const Finding*> out;
    for (const Finding& f : m_findings)
        if (f.object == ref)
            out.push_back(&f);
    return out;
}

std::optional<std::uint64_t> EditorChecks::ranOn(FindingSource source) const
{
    return m_ran[static_cast<int>(source)];
}

void EditorChecks::clear()
{
    m_findings.clear();
    m_summaries.clear();
    for (auto& ran : m_ran)
        ran.reset();
}

void EditorChecks::recheckAfterEdits(const SceneEditor& scene, bool busy, Trace& trace)
{
    // After every edit (once a drag or slider is let go): the geometry check always, the rest test when it has
    // run on this scene and the scene is small enough to test without a stall. Findings never go stale unseen.
    if (busy || scene.dragging() || scene.revision() == m_recheckedRevision)
        return;
    const bool firstLook = m_recheckedRevision == ~0ull;
    m_recheckedRevision = scene.revision();
    if (firstLook)
        return; // the scene as opened keeps its opening findings
    const LevelDef& level = scene.level();
    runGeometry(level, scene.revision());
    const bool rest = ranOn(FindingSource::Rest) && level.blocks.size() + level.pigs.size() <= kAutoRestBodies;
    if (rest)
        runRest(level, scene.revision());
    std::size_t geometry = 0;
    for (const Finding& finding : findings())
        geometry += finding.source == FindingSource::Geometry ? 1 : 0;
    trace.write("editor-recheck", {{"revision", scene.revision()}, {"geometry_findings", geometry}, {"rest", rest}});
}

} // namespace abalike::app

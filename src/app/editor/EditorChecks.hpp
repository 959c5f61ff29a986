#pragma once

#include <abalike/edit/Findings.hpp>

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// The checks a designer runs from the editor (the loader's geometry and reach checks, the 10 s rest test, the
/// solver) and what they found, marked on the objects. Geometry and rest run at once (milliseconds); the solver
/// runs on worker threads while the editor stays responsive.
class EditorChecks
{
public:
    EditorChecks() = default;
    ~EditorChecks();
    EditorChecks(const EditorChecks&) = delete;
    EditorChecks& operator=(const EditorChecks&) = delete;

    /// Findings a level was opened with (its geometry problems).
    void setOpeningIssues(const std::vector<LevelIssue>& issues, std::uint64_t revision);
    /// Overlaps, world bounds, pigs out of reach, the slingshot, the reference shot.
    void runGeometry(const LevelDef& level, std::uint64_t revision);
    /// The level left alone for 10 s: what moved or took damage.
    void runRest(const LevelDef& level, std::uint64_t revision);
    /// Starts the solver on a copy of the level (nothing happens if it is already running).
    void startSolver(const LevelDef& level, std::uint64_t revision);
    /// Collects the solver's result once it is done; call once per frame.
    void poll();

    bool solving() const { return m_solver.valid(); }
    /// Share of the solver's work done, 0 to 1.
    float solverProgress() const;

    const std::vector<Finding>& findings() const { return m_findings; }
    /// Findings on one object.
    std::vector<const Finding*> findingsOn(const ObjectRef& ref) const;
    /// The scene revision each source last ran on, to say when findings are out of date.
    std::optional<std::uint64_t> ranOn(FindingSource source) const;
    /// One line per source saying what it found ("geometry: 2 problems", "rest: stands still").
    const std::vector<std::string>& summaries() const { return m_summaries; }
    void clear();

private:
    void replace(FindingSource source, std::vector<Finding> findings, std::uint64_t revision, std::string summary);

    std::vector<Finding> m_findings;
    std::vector<std::string> m_summaries;
    std::optional<std::uint64_t> m_ran[3];
    struct Progress
    {
        std::atomic<std::size_t> done{0};
        std::atomic<std::size_t> total{1};
    };
    std::shared_ptr<Progress> m_progress = std::make_shared<Progress>();
    std::future<std::vector<Finding>> m_solver;
    std::uint64_t m_solverRevision = 0;
};

} // namespace abalike::app

#pragma once

#include <abalike/edit/Findings.hpp>
#include <abalike/edit/SceneEditor.hpp>

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class Trace;

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
    /// Runs the rest test unless it has already run on this revision, when the scene is small enough to test without
    /// a stall (saving lists what `abalike check` will say).
    void refreshRest(const LevelDef& level, std::uint64_t revision);
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
    /// After every edit, once it is complete (not while busy: a drag, a handle or a widget held, the scene playing):
    /// the geometry check, and the rest test when it has run on this scene and the scene is small enough to test
    /// without a stall. The scene as opened keeps its opening findings.
    void recheckAfterEdits(const SceneEditor& scene, bool busy, Trace& trace);

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
    std::uint64_t m_recheckedRevision = ~0ull; ///< the revision the automatic re-check last ran on
};

} // namespace abalike::app

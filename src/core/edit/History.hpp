#pragma once

#include "edit/EditCommand.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <string>

namespace abalike
{

/// The undo and redo stacks of a scene. Every edit goes through push(), which applies it; the history can then take
/// the level back and forth through exactly the states it has been in.
class History
{
public:
    /// At most `limit` edits are kept; the oldest are forgotten first.
    explicit History(std::size_t limit = 1000) : m_limit(limit) {}

    /// Applies the edit and records it. An edit that continues the last one (the same drag or slider, see
    /// EditCommand::merge) joins it while the gesture is open; push() opens the gesture, seal() closes it.
    void push(std::unique_ptr<EditCommand> command, LevelDef& level);
    /// Ends the current gesture: the next edit starts a new undo step.
    void seal() { m_open = false; }

    /// Reverts the last edit; returns it (for the selection it restores), or nullptr when there is none.
    const EditCommand* undo(LevelDef& level);
    /// Applies the last undone edit again; nullptr when there is none.
    const EditCommand* redo(LevelDef& level);

    bool canUndo() const { return !m_done.empty(); }
    bool canRedo() const { return !m_undone.empty(); }
    std::string undoLabel() const { return m_done.empty() ? std::string() : m_done.back().command->label(); }
    std::string redoLabel() const { return m_undone.empty() ? std::string() : m_undone.back().command->label(); }

    /// Names the level's current state: equal values mean equal levels (what was saved is compared with it).
    std::uint64_t state() const { return m_done.empty() ? m_baseState : m_done.back().state; }

private:
    struct Entry
    {
        std::unique_ptr<EditCommand> command;
        std::uint64_t state = 0; ///< the state once this edit is applied
    };

    std::size_t m_limit;
    std::deque<Entry> m_done;
    std::deque<Entry> m_undone;
    bool m_open = false;
    std::uint64_t m_nextState = 1;
    std::uint64_t m_baseState = 0; ///< the state below the oldest kept edit
};

} // namespace abalike

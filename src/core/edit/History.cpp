#include "edit/History.hpp"

namespace abalike
{

void History::push(std::unique_ptr<EditCommand> command, LevelDef& level)
{
    command->apply(level);
    m_undone.clear();
    if (m_open && !m_done.empty() && m_done.back().command->merge(*command))
    {
        m_done.back().state = m_nextState++; // the merged edit ends in a new state
        return;
    }
    m_done.push_back({std::move(command), m_nextState++});
    m_open = true;
    while (m_done.size() > m_limit)
    {
        m_baseState = m_done.front().state;
        m_done.pop_front();
    }
}

const EditCommand* History::undo(LevelDef& level)
{
    m_open = false;
    if (m_done.empty())
        return nullptr;
    m_done.back().command->revert(level);
    m_undone.push_back(std::move(m_done.back()));
    m_done.pop_back();
    return m_undone.back().command.get();
}

const EditCommand* History::redo(LevelDef& level)
{
    m_open = false;
    if (m_undone.empty())
        return nullptr;
    m_undone.back().command->apply(level);
    m_done.push_back(std::move(m_undone.back()));
    m_undone.pop_back();
    return m_done.back().command.get();
}

} // namespace abalike

#include "shell/ScreenStack.hpp"

#include <SFML/Graphics/Sprite.hpp>

namespace abalike::app
{

void ScreenStack::push(std::unique_ptr<Screen> screen)
{
    if (screen)
        m_pending.push_back({Change::Push, std::move(screen)});
}

void ScreenStack::pop()
{
    m_pending.push_back({Change::Pop, nullptr});
}

void ScreenStack::replace(std::unique_ptr<Screen> screen)
{
    pop();
    push(std::move(screen));
}

void ScreenStack::clear()
{
    m_pending.push_back({Change::Clear, nullptr});
}

bool ScreenStack::applyPending()
{
    if (m_pending.empty())
        return false;
    m_snapshotValid = false;
    // Screens may queue more changes while being created or resumed: take the queue first.
    std::vector<Pending> pending = std::move(m_pending);
    m_pending.clear();
    Screen* const topBefore = top();
    std::vector<const Screen*> pushedScreens;
    for (Pending& item : pending)
    {
        switch (item.change)
        {
        case Change::Push:
            pushedScreens.push_back(item.screen.get());
            notify("push", *item.screen);
            m_screens.push_back(std::move(item.screen));
            break;
        case Change::Pop:
            if (!m_screens.empty())
            {
                notify("pop", *m_screens.back());
                m_screens.pop_back();
            }
            break;
        case Change::Clear:
            while (!m_screens.empty())
            {
                notify("pop", *m_screens.back());
                m_screens.pop_back();
            }
            break;
        }
    }
    // A screen that was already on the stack and is now uncovered is told; a newly pushed one is not.
    Screen* const now = top();
    if (now != nullptr && now != topBefore)
    {
        bool pushedNow = false;
        for (std::size_t i = 0; i < pushedScreens.size() && !pushedNow; ++i)
            pushedNow = pushedScreens[i] == now;
        if (!pushedNow)
            now->onResume();
    }
    return true;
}

std::vector<std::string> ScreenStack::names() const
{
    std::vector<std::string> out;
    for (const auto& screen : m_screens)
        out.emplace_back(screen->name());
    return out;
}

Screen* ScreenStack::below(const Screen* screen) const
{
    for (std::size_t i = 1; i < m_screens.size(); ++i)
        if (m_screens[i].get() == screen)
            return m_screens[i - 1].get();
    return nullptr;
}

void ScreenStack::draw(sf::RenderTarget& target) const
{
    if (m_screens.empty())
        return;
    std::size_t first = m_screens.size() - 1;
    while (first > 0 && m_screens[first]->isOverlay())
        --first;
    for (std::size_t i = first; i < m_screens.size(); ++i)
        m_screens[i]->draw(target);
}

void ScreenStack::drawWithSnapshot(sf::RenderWindow& window)
{
    if (m_screens.empty())
        return;
    const std::size_t topIndex = m_screens.size() - 1;
    std::size_t first = topIndex;
    while (first > 0 && m_screens[first]->isOverlay())
        --first;
    bool covered = first < topIndex;
    for (std::size_t i = first; i < topIndex && covered; ++i)
        covered = !m_screens[i]->changesWhileCovered();
    if (!covered)
    {
        m_snapshotValid = false;
        draw(window);
        return;
    }
    const sf::Vector2u size = window.getSize();
    if (m_snapshotValid && m_snapshot->getSize() == size)
    {
        const sf::View view = window.getView();
        window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(size.x), static_cast<float>(size.y))));
        window.draw(sf::Sprite(*m_snapshot), sf::RenderStates(sf::BlendNone));
        window.setView(view);
    }
    else
    {
        for (std::size_t i = first; i < topIndex; ++i)
            m_screens[i]->draw(window);
        if (!m_snapshot)
            m_snapshot = std::make_unique<sf::Texture>();
        m_snapshotValid = m_snapshot->getSize() == size || m_snapshot->create(size.x, size.y);
        if (m_snapshotValid)
            m_snapshot->update(window);
    }
    m_screens[topIndex]->draw(window);
}

void ScreenStack::finishBackgroundWork()
{
    for (const auto& screen : m_screens)
        screen->finishBackgroundWork();
}

void ScreenStack::resize(sf::Vector2u size)
{
    m_snapshotValid = false;
    for (const auto& screen : m_screens)
        screen->onResize(size);
}

void ScreenStack::notify(std::string_view change, const Screen& screen) const
{
    if (m_observer)
        m_observer(change, screen.name());
}

} // namespace abalike::app

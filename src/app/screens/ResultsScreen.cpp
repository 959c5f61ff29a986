#include "screens/ResultsScreen.hpp"

#include "endless/EndlessGame.hpp"
#include "render/TextFormat.hpp"
#include "screens/Navigation.hpp"
#include "screens/PlayScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/RunControl.hpp"
#include "shell/UiMetrics.hpp"

namespace abalike::app
{

namespace
{
std::string castles(int n)
{
    return std::to_string(n) + (n == 1 ? " castle" : " castles");
}

/// The endless run's lines on the card: where the run stands (or what it achieved), the bests, and how to play this
/// level again.
std::vector<std::string> endlessNotes(AppContext& app, const PlayScreen& play, bool won)
{
    const EndlessGame& endless = app.progress().endless();
    const EndlessRecord& best = app.progress().current().endless;
    std::vector<std::string> notes;
    if (won)
        notes.push_back("Run: " + castles(endless.run().levelsWon()) + " won, " + formatPoints(endless.run().score()) +
                        " points. Next: harder");
    else
        notes.push_back("Run over: " + castles(endless.lastRunEnded().levelsWon) + " won, " +
                        formatPoints(endless.lastRunEnded().score) + " points");
    notes.push_back("Best run: " + castles(best.longestRun) + "; best score " + formatPoints(best.bestScore));
    notes.push_back("Replay: abalike play --generated " + play.source().endless->generatedName());
    return notes;
}
} // namespace

ResultsScreen::ResultsScreen(AppContext& app, PlayScreen& play) : m_app(app), m_play(play), m_panel(app.ui().font())
{
    const bool won = play.session().phase() == Phase::Won;
    std::vector<MenuItem> items;
    if (play.endless())
    {
        // The run goes on after a win and starts again after a loss; a level is never retried inside a run.
        m_notes = endlessNotes(app, play, won);
        items.push_back({"next", won ? "Next castle" : "New run", true});
        items.push_back({"title", "Title", true});
    }
    else
    {
        if (won && play.nextLevelIndex().has_value())
            items.push_back({"next", "Next level", true});
        items.push_back({"retry", "Retry", true});
        items.push_back({"levels", "Level select", !app.progress().campaign().levels.empty()});
    }
    m_menu.setItems(std::move(items));
    for (int key = 0; key < sf::Keyboard::KeyCount; ++key)
        m_heldAtOpen[static_cast<std::size_t>(key)] = app.run().input().keyDown(static_cast<sf::Keyboard::Key>(key));
}

void ResultsScreen::handleEvent(const sf::Event& event)
{
    const bool keyEvent = event.type == sf::Event::KeyPressed || event.type == sf::Event::KeyReleased;
    const auto key = keyEvent && event.key.code >= 0 && event.key.code < sf::Keyboard::KeyCount
                         ? static_cast<std::size_t>(event.key.code)
                         : m_heldAtOpen.size();
    if (key < m_heldAtOpen.size() && m_heldAtOpen[key])
    {
        // A key held since before the card opened: its release ends that, its repeats are not a choice.
        if (event.type == sf::Event::KeyReleased)
            m_heldAtOpen[key] = false;
        return;
    }
    const bool input = keyEvent || event.type == sf::Event::MouseButtonPressed ||
                       event.type == sf::Event::MouseButtonReleased || event.type == sf::Event::JoystickButtonPressed;
    if (input && m_shownS < kIgnoreInputS)
        return;
    if (event.type == sf::Event::KeyPressed)
    {
        switch (event.key.code)
        {
        case sf::Keyboard::R:
            activate("retry");
            return;
        case sf::Keyboard::N:
            activate("next");
            return;
        case sf::Keyboard::Escape:
            activate("levels");
            return;
        default:
            break;
        }
    }
    if (const std::optional<std::string> id = m_menu.handleEvent(event))
        activate(*id);
}

void ResultsScreen::activate(const std::string& id)
{
    if (m_play.endless())
    {
        if (id == "next")
            m_play.goToNextLevel();
        else if (id == "title" || id == "levels")
            openTitle(m_app);
        return;
    }
    if (id == "retry")
    {
        m_play.restartLevel();
        m_app.navigator().screens().pop();
    }
    else if (id == "next" && m_play.nextLevelIndex() && m_play.session().phase() == Phase::Won)
    {
        m_app.navigator().screens().pop();
        m_play.goToNextLevel();
    }
    else if (id == "levels" && !m_app.progress().campaign().levels.empty())
        openLevelSelect(m_app);
}

void ResultsScreen::draw(sf::RenderTarget& target)
{
    const float scale = m_app.ui().scale();
    const unsigned itemSize = m_app.ui().textSize(20.0f);
    const float lineHeight = m_app.ui().font() != nullptr ? m_app.ui().font()->getLineSpacing(itemSize) : 20.0f;
    const float menuHeight = static_cast<float>(m_menu.items().size()) * (lineHeight + 22.0f * scale) + 12.0f * scale;
    const sf::FloatRect card = m_panel.draw(target, target.getSize(), m_play.session(), scale, menuHeight, m_notes);
    m_menu.draw(target, m_app.ui().font(), card.left + 0.5f * card.width, card.top + card.height + 12.0f * scale,
                std::min(card.width, 300.0f * scale), itemSize, scale);
}

} // namespace abalike::app

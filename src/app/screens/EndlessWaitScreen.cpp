#include "screens/EndlessWaitScreen.hpp"

#include "endless/EndlessGame.hpp"
#include "render/TextFormat.hpp"
#include "screens/EndlessNavigation.hpp"
#include "screens/Navigation.hpp"
#include "screens/PlayScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/ProgressCard.hpp"

#include <abalike/level/LevelWriter.hpp>
#include <cmath>

namespace abalike::app
{

namespace
{
/// About what one level takes on one low-priority core of a 2-core machine (bench generate: 37 s median on two).
constexpr double kTypicalWaitS = 60.0;
} // namespace

void EndlessWaitScreen::handleEvent(const sf::Event& event)
{
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Escape && !m_leaving)
    {
        m_leaving = true;
        openTitle(m_app);
    }
}

EndlessWaitScreen::EndlessWaitScreen(AppContext& app) : m_app(app)
{
    // Nothing else runs while the player waits: the level in progress gets every core.
    m_app.progress().endless().hurry(true);
}

EndlessWaitScreen::~EndlessWaitScreen()
{
    m_app.progress().endless().hurry(false);
}

void EndlessWaitScreen::frameUpdate(double frameS)
{
    m_waitedS += frameS;
    if (m_leaving || !m_app.progress().endless().problem().empty())
        return;
    if (std::unique_ptr<Screen> next = endlessLevelScreen(m_app))
    {
        m_leaving = true;
        m_app.navigator().screens().replace(std::move(next));
    }
}

void EndlessWaitScreen::draw(sf::RenderTarget& target)
{
    const EndlessGame& endless = m_app.progress().endless();
    const GeneratedLevelQueue::Status status = endless.generation();
    Progress progress;
    progress.title = "Building the next castle";
    if (!endless.problem().empty())
    {
        progress.title = "The endless mode cannot start";
        progress.detail = endless.problem();
    }
    else if (!status.error.empty())
        progress.detail = "Generating failed: " + status.error;
    else
        progress.detail = "Seed " + std::to_string(status.seed) + ", loss share " +
                          shortestNumber(status.lossShareTenths / 10.0) +
                          ": laying it out, checking that it stands, that it can be won and how often a player "
                          "loses it (" +
                          formatFixed(m_waitedS, 0) + " s; Esc: title)";
    // The generator does not know how long it will take: the bar fills towards a typical wait and then creeps.
    progress.fraction = static_cast<float>(1.0 - std::exp(-m_waitedS / kTypicalWaitS));
    drawProgressCard(target, m_app.ui().font(), progress, m_app.ui().textSize(22.0f), m_app.ui().textSize(15.0f),
                     m_app.ui().scale());
}

} // namespace abalike::app

#pragma once

#include "render/ResultsPanel.hpp"
#include "shell/Screen.hpp"
#include "ui/MenuList.hpp"

#include <SFML/Window/Keyboard.hpp>
#include <array>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;
class PlayScreen;

/// The end-of-level card over the finished level: won or lost, the score breakdown and stars, then retry, next
/// level or level select (R and N work too). For its first kIgnoreInputS it takes no input, nor afterwards a key
/// held since before it opened: a Space pressed for the bird's ability a moment earlier must not restart the level.
class ResultsScreen : public Screen
{
public:
    static constexpr std::string_view kName = "results";

    ResultsScreen(AppContext& app, PlayScreen& play);

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void frameUpdate(double frameS) override { m_shownS += frameS; }
    void draw(sf::RenderTarget& target) override;

    static constexpr double kIgnoreInputS = 0.5;

private:
    void activate(const std::string& id);

    AppContext& m_app;
    PlayScreen& m_play;
    ResultsPanel m_panel;
    MenuList m_menu;
    std::vector<std::string> m_notes; ///< the endless run's lines under the total
    double m_shownS = 0.0;
    std::array<bool, sf::Keyboard::KeyCount> m_heldAtOpen{}; ///< keys down when it opened: ignored until released
};

} // namespace abalike::app

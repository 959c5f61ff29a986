#pragma once

#include "render/ResultsPanel.hpp"
#include "screens/Screen.hpp"
#include "ui/MenuList.hpp"

namespace abalike::app
{

class App;
class PlayScreen;

/// The end-of-level card over the finished level: won or lost, the score breakdown and stars, then retry, next
/// level or level select (R and N work too).
class ResultsScreen : public Screen
{
public:
    static constexpr std::string_view kName = "results";

    ResultsScreen(App& app, PlayScreen& play);

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    void activate(const std::string& id);

    App& m_app;
    PlayScreen& m_play;
    ResultsPanel m_panel;
    MenuList m_menu;
};

} // namespace abalike::app

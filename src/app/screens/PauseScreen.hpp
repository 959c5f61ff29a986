#pragma once

#include "shell/Screen.hpp"
#include "ui/MenuList.hpp"

namespace abalike::app
{

class AppContext;
class PlayScreen;

/// The pause menu over a level (Esc or P): resume, restart, settings, controls, level select, quit. The level stands
/// still underneath until it is resumed.
class PauseScreen : public Screen
{
public:
    static constexpr std::string_view kName = "pause";

    PauseScreen(AppContext& app, PlayScreen& play);

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    void activate(const std::string& id);
    /// The pause menu, or the question whether to quit the game from a running level.
    void showMenu(bool confirmQuit);

    AppContext& m_app;
    PlayScreen& m_play;
    MenuList m_menu;
    bool m_confirmingQuit = false;
};

} // namespace abalike::app

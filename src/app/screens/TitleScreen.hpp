#pragma once

#include "render/Camera.hpp"
#include "render/WorldRenderer.hpp"
#include "shell/Screen.hpp"
#include "ui/MenuList.hpp"

#include <abalike/game/GameSession.hpp>
#include <memory>

namespace abalike::app
{

class AppContext;

/// The title: the game's name over the first level's scenery, and the main menu (play, level select, controls,
/// quit; lessons, sandbox and settings join it as they exist).
class TitleScreen : public Screen
{
public:
    static constexpr std::string_view kName = "title";

    explicit TitleScreen(AppContext& app);

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;
    void onResize(sf::Vector2u size) override;

private:
    void activate(const std::string& id);

    AppContext& m_app;
    MenuList m_menu;
    std::unique_ptr<GameSession> m_scenery; ///< the first level, drawn still behind the menu
    Camera m_camera;
    WorldRenderer m_world;
};

} // namespace abalike::app

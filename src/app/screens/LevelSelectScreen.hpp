#pragma once

#include "render/Mesh.hpp"
#include "shell/Screen.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <cstddef>
#include <optional>
#include <vector>

namespace abalike::app
{

class AppContext;

/// Episodes and their levels as tiles: stars and best score from the saved progress, locked levels dimmed, and
/// the selected level's title and the concept it teaches. Arrows and Enter, or hover and click; Esc goes back.
class LevelSelectScreen : public Screen
{
public:
    static constexpr std::string_view kName = "level-select";

    explicit LevelSelectScreen(AppContext& app);

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

    /// The campaign index of the selected tile.
    std::size_t selected() const { return m_selected; }

private:
    /// Moves the selection by whole tiles within an episode (dx) or between episodes (dy).
    void move(int dx, int dy);
    void play(std::size_t index);
    std::optional<std::size_t> tileAt(int x, int y) const;
    /// (episode, position in episode) of a campaign index.
    std::pair<std::size_t, std::size_t> place(std::size_t index) const;

    AppContext& m_app;
    std::size_t m_selected = 0;
    std::vector<sf::FloatRect> m_tiles; ///< where each level's tile was drawn, by campaign index
    std::optional<std::size_t> m_pressed;
    Mesh m_mesh;
};

} // namespace abalike::app

#pragma once

#include "play/PlayLayer.hpp"
#include "render/Camera.hpp"
#include "render/ShotTrails.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/game/GameSession.hpp>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// What the teaching overlay adds to the kept shot paths (ShotTrails, the play screen's): PhET's timing dots -- small
/// every 0.1 s, large every 1 s -- and the measuring tools: hover (or click while no bird flies) on any point of a
/// kept path or the preview for t, x, y, speed and height; a tape measure dragged with the right mouse button.
class PathHistory
{
public:
    /// A level started or restarted: let go of a pinned reading.
    void onLevelStart();
    /// Forgets the tape and the reading (key C; the play screen clears the paths).
    void clear();
    /// Mouse input for hover, pinning and the tape; true when the event was used.
    bool handleEvent(const sf::Event& event, const PlayView& view);
    /// The same tools by keyboard: M pins a reading on the newest kept path (again: the next older path, then off),
    /// comma and period walk it by 0.1 s (Shift: 1 s), L starts the tape at the reading (the tape's other end
    /// follows the reading) and removes it. True when the key was used.
    bool handleKey(const sf::Event::KeyEvent& key, const PlayView& view);

    /// The dots on every kept path, older paths fainter.
    static void drawDots(sf::RenderTarget& target, const ShotTrails& trails, const Camera& camera, float scale);
    /// The tape and the hovered or pinned point's readout.
    void drawTools(sf::RenderTarget& target, const sf::Font& font, const Camera& camera, const GameSession& session,
                   unsigned rowSize, float scale) const;

    /// True once a path point was read or the tape used.
    bool used() const { return m_used; }

private:
    struct Pick
    {
        std::string path;
        PathSample sample;
    };
    /// The path point nearest to a window position, within a few pixels.
    static std::optional<Pick> pick(sf::Vector2f pixel, const PlayView& view, float radiusPx);
    /// A window position snapped to a path point if one is near, in world metres.
    static sf::Vector2f snap(sf::Vector2f pixel, const PlayView& view);

    /// Pins the reading at time t of the kept path counted from the newest (0), or lets go past the oldest.
    void pinOnPath(const PlayView& view, std::size_t fromNewest, double t);

    std::optional<Pick> m_hover;
    std::optional<std::size_t> m_keyPath; ///< the kept path the keyboard reading walks, counted from the newest
    double m_keyT = 0.0;
    bool m_pinned = false;
    std::optional<std::array<sf::Vector2f, 2>> m_tape; ///< ends in world metres
    bool m_taping = false;
    bool m_keyTape = false; ///< the tape's far end follows the keyboard reading
    bool m_used = false;
};

} // namespace abalike::app

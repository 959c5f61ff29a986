#pragma once

#include "render/CameraRig.hpp"

#include <SFML/Window/Event.hpp>
#include <optional>

namespace abalike::app
{

/// The player's hands on the camera: the wheel zooms about the pointer, + and − (also = and -) zoom about the middle,
/// W A S D pan (Shift: further), Home or 0 goes back to the automatic camera; a drag with the middle button, or with
/// the left button where a left click does nothing else (empty sky while aiming, any time no bird can be aimed or
/// use its ability), pans. It only reads events and moves the rig.
class CameraControls
{
public:
    static constexpr float kWheelZoom = 1.15f; ///< per wheel notch
    static constexpr float kKeyZoom = 1.25f;   ///< per + or − press
    static constexpr float kKeyPanPx = 60.0f;  ///< per W A S D press (Shift: 4 times that)
    static constexpr float kDragStartPx = 3.0f;

    /// Handles one event. leftIsFree says whether a left press here would do nothing else (the play screen knows:
    /// not on the bird, not an ability). True when the camera used the event.
    bool handleEvent(const sf::Event& event, CameraRig& rig, bool leftIsFree);
    /// A drag is moving the camera (the play screen then ignores the pointer for aiming).
    bool panning() const { return m_dragFrom.has_value(); }

private:
    std::optional<sf::Vector2f> m_dragFrom;
    bool m_dragMoved = false;
};

} // namespace abalike::app

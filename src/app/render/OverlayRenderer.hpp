#pragma once

#include "render/Camera.hpp"
#include "render/Mesh.hpp"

#include <abalike/game/GameSession.hpp>

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <array>
#include <optional>
#include <span>

namespace abalike::app
{

/// What the overlay shows of one fired shot; the paths may still be growing while the bird flies.
struct ShotOverlay
{
    std::span<const std::array<double, 3>> predictedPath; ///< (t, x, y)
    std::span<const std::array<double, 3>> actualPath;    ///< (t, x, y)
    std::optional<ContactPoint> predictedContact;
    std::optional<ContactPoint> actualContact;
    std::optional<double> deviationM;
};

/// Draws prediction against reality: the RK4 preview as dots, the flown path as a solid orange line, rings
/// and crosses where each says the first contact is, and how far apart they are.
class OverlayRenderer
{
public:
    /// font may be null: then the deviation label is left out.
    explicit OverlayRenderer(const sf::Font* font) : m_font(font) {}

    /// The preview of the current aim: a dot per step and a ring at the predicted contact.
    void drawPreview(sf::RenderTarget& target, const Camera& camera, const PredictedFlight& preview);
    /// A fired shot, at the given opacity (older shots fade).
    void drawShot(sf::RenderTarget& target, const Camera& camera, const ShotOverlay& shot, float opacity);

private:
    void addDots(const Camera& camera, std::span<const sf::Vector2f> worldPoints, float radius, float opacity);
    void addPredictedContact(const Camera& camera, const ContactPoint& contact, float opacity);

    const sf::Font* m_font;
    Mesh m_mesh;
};

} // namespace abalike::app

#pragma once

#include "render/Camera.hpp"
#include "render/Mesh.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>
#include <span>

namespace abalike::app
{

/// Draws prediction against reality: the RK4 preview as dots, the flown path as a solid orange line, rings
/// and crosses where each says the first contact is, and how far apart they are; where an ability was used and
/// the impulses it applied.
/// How many of a preview's dots the short preview (Game mode's, "first dots") shows: the climb to the top of the arc,
/// and never less than half a second (a shot aimed level or down has no climb). The aim, not the landing.
std::size_t shortPreviewDots(const PredictedFlight& preview);

class OverlayRenderer
{
public:
    /// font may be null: then the deviation label is left out.
    explicit OverlayRenderer(const sf::Font* font) : m_font(font) {}

    /// The preview of the current aim: a dot per step and a ring at the predicted contact; with maxDots, only the
    /// first dots and no ring (shortPreviewDots).
    void drawPreview(sf::RenderTarget& target, const Camera& camera, const PredictedFlight& preview,
                     std::size_t maxDots = 0);
    /// The paths of a fired shot, at the given opacity (older shots fade); drawn behind blocks and birds.
    void drawShotPaths(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot, float opacity);
    /// The contact markers and the deviation label of a fired shot; drawn over everything.
    /// The predicted and actual contact and the ability's impulses.
    void drawShotMarkers(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot, float opacity);
    /// The "predicted vs actual" label next to the actual contact, drawn after every panel: clear of them
    /// (ScreenRegions) and of `keep` (the live pigs, the flying bird, the landing point, the slingshot) and, where
    /// there is room, of the boxes in structure (on screen); left out when no spot near the contact inside the window
    /// is clear of the panels and of `keep`. textScale is the player's setting. chip: the game mode's small chip with
    /// the distance alone, instead of the sentence.
    void drawShotLabel(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot, float opacity,
                       std::span<const sf::FloatRect> structure, std::span<const sf::FloatRect> keep, float textScale,
                       bool chip = false);

private:
    void addDots(const Camera& camera, std::span<const sf::Vector2f> worldPoints, float radius, float opacity);
    void addPredictedContact(const Camera& camera, const ContactPoint& contact, float opacity);
    /// A burst where the ability was used and an arrow per impulse it applied.
    void addAbility(const Camera& camera, const AbilityUse& ability, float opacity);

    const sf::Font* m_font;
    Mesh m_mesh;
};

} // namespace abalike::app

#pragma once

#include "fx/CameraShake.hpp"
#include "fx/Particles.hpp"
#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Text.hpp>
#include <SFML/System/Vector2.hpp>
#include <string>
#include <vector>

namespace abalike::app
{

/// Break debris by material and score pop-ups where things were destroyed, driven by GameSession::destroyed().
/// Heavy breaks (stone, pigs) and explosions shake the world view a little. Visual only: it reads the session and
/// never changes it. Reduced motion: a quarter of the pieces, pop-ups that fade in place, and no shake.
class FxLayer : public PlayLayer
{
public:
    std::string_view name() const override { return "fx"; }
    void onLevelStart(PlayView& view) override;
    void afterStep(PlayView& view) override;
    void frameUpdate(PlayView& view, double frameS) override;
    void drawWorld(sf::RenderTarget& target, PlayView& view) override;
    void drawScreen(sf::RenderTarget& target, PlayView& view) override;
    sf::Vector2f worldShakePx(PlayView& view) const override;

private:
    struct PopUp
    {
        sf::Vector2f positionM;
        float ageS = 0.0f;
        bool pig = false;
        /// The points, bold and outlined, made with the pop-up and kept: sf::Text lays its glyphs out again (asking
        /// FreeType for every pair's kerning) only when its string, font or size changes, not when it fades or rises.
        sf::Text label;
    };

    Particles m_particles;
    std::vector<PopUp> m_popUps;
    std::size_t m_seen = 0;          ///< events of session.destroyed() already turned into effects
    std::size_t m_abilitiesSeen = 0; ///< shots whose ability use has been shown
    std::size_t m_blastsSeen = 0;    ///< TNT blasts of session.blasts() already shown
    CameraShake m_shake;
    Mesh m_mesh;
};

} // namespace abalike::app

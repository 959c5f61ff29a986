#pragma once

#include "render/Mesh.hpp"

#include <SFML/Graphics/Color.hpp>
#include <SFML/System/Vector2.hpp>
#include <abalike/world/Looks.hpp>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// Debris and puffs thrown out when something breaks: purely visual, in world metres (y up), never touching the
/// simulation. Seeded, so the same events give the same pictures (screenshots stay reproducible).
class Particles
{
public:
    /// What a piece looks like.
    enum class Shape
    {
        Splinter, ///< wood: a thin spinning slat
        Shard,    ///< ice: a translucent triangle
        Chunk,    ///< stone: a rough quad
        Puff,     ///< a pig popping: a growing, fading cloud
        Flash,    ///< a blast: a bright disc that grows to the blast radius and fades fast
        Ring,     ///< a blast's shock wave: a thin ring that runs out past the blast radius
        Smoke,    ///< a blast's smoke: a dark cloud that rises and spreads slowly
    };

    /// Starts over with no pieces and a fixed seed.
    void reset();
    /// Throws out the pieces of a broken block of the given material and size at (x, y); `count` pieces.
    void burstBlock(const MaterialLook& material, sf::Vector2f centreM, float sizeM, int count);
    /// A cloud of green and white puffs where a pig was defeated.
    void burstPig(sf::Vector2f centreM, float radiusM, int count);
    /// A grey puff where a bird leaves the world after its shot.
    void burstBird(sf::Vector2f centreM, float radiusM, int count);
    /// A blast of radius radiusM (TNT, the black bird): a flash, a shock ring running out to 1.3 radii, orange fire
    /// and dark smoke that rises for a second or two; count sets how many fire and smoke puffs (fewer with reduced
    /// motion).
    void burstBlast(sf::Vector2f centreM, float radiusM, int count);
    /// The level's ground line (m): falling debris lands on it and bounces a little instead of sinking through it.
    void setFloor(float yM) { m_floorY = yM; }
    /// Moves every piece on by dtS (ballistic, with a little air drag) and retires the expired ones.
    void update(float dtS);
    /// Adds every piece to the mesh, in world metres.
    void paint(Mesh& mesh) const;

    std::size_t size() const { return m_pieces.size(); }
    /// Where every piece is now (metres).
    std::vector<sf::Vector2f> positionsM() const;

private:
    struct Piece
    {
        Shape shape = Shape::Chunk;
        sf::Vector2f positionM;
        sf::Vector2f velocityMps;
        float angleRad = 0.0f;
        float spinRadps = 0.0f;
        float sizeM = 0.1f;
        float ageS = 0.0f;
        float lifeS = 1.0f;
        sf::Color colour;
    };

    /// A cloud of puffs: speeds, start (share of the radius), upward drift, sizes (share of the radius), lives,
    /// and the two colours they alternate.
    struct PuffStyle
    {
        float minSpeed, maxSpeed, startShare, rise, minSize, maxSize, minLife, maxLife;
        sf::Color even, odd;
    };
    void burstPuffs(sf::Vector2f centreM, float radiusM, int count, const PuffStyle& style);

    /// Uniform in [lo, hi).
    float uniform(float lo, float hi);

    std::vector<Piece> m_pieces;
    float m_floorY = -std::numeric_limits<float>::infinity();
    std::uint32_t m_state = 1;
};

} // namespace abalike::app

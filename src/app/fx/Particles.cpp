#include "fx/Particles.hpp"

#include "render/Palette.hpp"

#include <SFML/Graphics/Transform.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace abalike::app
{

namespace
{

constexpr float kGravityMps2 = 9.81f;
constexpr float kDragPerS = 0.6f;        ///< velocity lost per second, so pieces do not fly like bullets
constexpr std::size_t kMaxPieces = 1500; ///< a 1 000-block collapse must not grow the frame time without bound

Particles::Shape shapeFor(SurfaceKind surface)
{
    switch (surface)
    {
    case SurfaceKind::Frost:
        return Particles::Shape::Shard;
    case SurfaceKind::Masonry:
        return Particles::Shape::Chunk;
    case SurfaceKind::Grain:
    case SurfaceKind::Crate:
        break;
    }
    return Particles::Shape::Splinter;
}

} // namespace

void Particles::reset()
{
    m_pieces.clear();
    m_state = 0x2545F491u;
}

float Particles::uniform(float lo, float hi)
{
    // xorshift32: tiny, and the same on every platform (std distributions are not).
    m_state ^= m_state << 13;
    m_state ^= m_state >> 17;
    m_state ^= m_state << 5;
    return lo + (hi - lo) * static_cast<float>(m_state >> 8) / 16777216.0f;
}

void Particles::burstBlock(const MaterialLook& material, sf::Vector2f centreM, float sizeM, int count)
{
    const MaterialColours colours = materialColours(material);
    const Shape shape = shapeFor(material.surface);
    for (int i = 0; i < count && m_pieces.size() < kMaxPieces; ++i)
    {
        Piece piece;
        piece.shape = shape;
        piece.positionM = centreM + sf::Vector2f(uniform(-0.4f, 0.4f), uniform(-0.4f, 0.4f)) * sizeM;
        const float angle = uniform(0.15f, std::numbers::pi_v<float> - 0.15f); // mostly upwards
        const float speed = uniform(1.5f, 5.0f);
        piece.velocityMps = {speed * std::cos(angle), speed * std::sin(angle)};
        piece.angleRad = uniform(0.0f, 6.28f);
        piece.spinRadps = uniform(-12.0f, 12.0f);
        piece.sizeM = sizeM * uniform(0.3f, 0.55f);
        piece.lifeS = uniform(0.9f, 1.6f);
        const int pick = i % 3;
        // The outline colour for a third of the pieces: ice's fill alone vanishes against a pale sky.
        piece.colour = pick == 0 ? colours.outline : pick == 1 ? colours.fill : colours.detail;
        piece.colour.a = shape == Shape::Shard ? 230 : 255;
        m_pieces.push_back(piece);
    }
}

void Particles::burstPuffs(sf::Vector2f centreM, float radiusM, int count, const PuffStyle& style)
{
    for (int i = 0; i < count && m_pieces.size() < kMaxPieces; ++i)
    {
        Piece piece;
        piece.shape = Shape::Puff;
        const float angle = uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
        const float speed = uniform(style.minSpeed, style.maxSpeed);
        piece.positionM = centreM + sf::Vector2f(std::cos(angle), std::sin(angle)) * (radiusM * style.startShare);
        piece.velocityMps = {speed * std::cos(angle), speed * std::sin(angle) + style.rise};
        piece.sizeM = radiusM * uniform(style.minSize, style.maxSize);
        piece.lifeS = uniform(style.minLife, style.maxLife);
        piece.colour = i % 2 == 0 ? style.even : style.odd;
        m_pieces.push_back(piece);
    }
}

void Particles::burstPig(sf::Vector2f centreM, float radiusM, int count)
{
    burstPuffs(centreM, radiusM, count,
               {0.4f, 1.6f, 0.5f, 0.6f, 0.35f, 0.6f, 0.6f, 1.0f, palette::kPig, sf::Color(245, 248, 240)});
}

void Particles::burstBird(sf::Vector2f centreM, float radiusM, int count)
{
    burstPuffs(
        centreM, radiusM, count,
        {0.3f, 1.0f, 0.4f, 0.4f, 0.4f, 0.7f, 0.5f, 0.8f, sf::Color(236, 236, 232, 220), sf::Color(200, 200, 196, 200)});
}

void Particles::burstBlast(sf::Vector2f centreM, float radiusM, int count)
{
    if (m_pieces.size() < kMaxPieces)
    {
        Piece flash;
        flash.shape = Shape::Flash;
        flash.positionM = centreM;
        flash.sizeM = radiusM;
        flash.lifeS = 0.35f;
        flash.colour = sf::Color(255, 236, 150, 230);
        m_pieces.push_back(flash);
    }
    if (m_pieces.size() < kMaxPieces)
    {
        Piece ring;
        ring.shape = Shape::Ring;
        ring.positionM = centreM;
        ring.sizeM = 1.3f * radiusM;
        ring.lifeS = 0.45f;
        ring.colour = sf::Color(255, 250, 235, 200);
        m_pieces.push_back(ring);
    }
    // Smoke: dark puffs that linger and rise once the fire is gone.
    for (int i = 0; i < count / 2 && m_pieces.size() < kMaxPieces; ++i)
    {
        Piece smoke;
        smoke.shape = Shape::Smoke;
        const float angle = uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
        const float distance = radiusM * uniform(0.0f, 0.5f);
        smoke.positionM = centreM + distance * sf::Vector2f(std::cos(angle), std::sin(angle));
        smoke.velocityMps = {uniform(-0.3f, 0.3f), uniform(0.6f, 1.2f)};
        smoke.sizeM = radiusM * uniform(0.18f, 0.3f);
        smoke.lifeS = uniform(1.2f, 2.0f);
        smoke.colour = sf::Color(70, 66, 64, 170);
        m_pieces.push_back(smoke);
    }
    for (int i = 0; i < count && m_pieces.size() < kMaxPieces; ++i)
    {
        Piece piece;
        piece.shape = Shape::Puff;
        const float angle = uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
        const float speed = uniform(1.0f, 3.0f);
        piece.positionM = centreM;
        piece.velocityMps = {speed * std::cos(angle), speed * std::sin(angle) + 0.8f};
        piece.sizeM = radiusM * uniform(0.1f, 0.2f);
        piece.lifeS = uniform(0.5f, 0.9f);
        piece.colour = i % 3 == 0 ? sf::Color(90, 84, 80, 200) : sf::Color(250, 150, 40, 210);
        m_pieces.push_back(piece);
    }
}

void Particles::update(float dtS)
{
    for (Piece& piece : m_pieces)
    {
        piece.ageS += dtS;
        // Puffs and flashes float; debris falls, and lands on the ground rather than sinking into it.
        const bool falls = piece.shape != Shape::Puff && piece.shape != Shape::Flash && piece.shape != Shape::Ring &&
                           piece.shape != Shape::Smoke;
        if (falls)
            piece.velocityMps.y -= kGravityMps2 * dtS;
        piece.velocityMps *= std::max(0.0f, 1.0f - kDragPerS * dtS);
        piece.positionM += piece.velocityMps * dtS;
        piece.angleRad += piece.spinRadps * dtS;
        const float bottom = m_floorY + 0.5f * piece.sizeM;
        if (falls && piece.positionM.y < bottom)
        {
            piece.positionM.y = bottom;
            if (piece.velocityMps.y < 0.0f)
                piece.velocityMps.y *= -0.3f;
            piece.velocityMps.x *= 0.7f;
            piece.spinRadps *= 0.7f;
        }
    }
    std::erase_if(m_pieces, [](const Piece& piece) { return piece.ageS >= piece.lifeS; });
}

std::vector<sf::Vector2f> Particles::positionsM() const
{
    std::vector<sf::Vector2f> positions;
    for (const Piece& piece : m_pieces)
        positions.push_back(piece.positionM);
    return positions;
}

void Particles::paint(Mesh& mesh) const
{
    for (const Piece& piece : m_pieces)
    {
        const float left = 1.0f - piece.ageS / piece.lifeS;
        // Fade over the last 40 % of a piece's life.
        const sf::Color colour = faded(piece.colour, std::min(1.0f, left / 0.4f));
        sf::Transform local;
        local.translate(piece.positionM).rotate(piece.angleRad * 180.0f / std::numbers::pi_v<float>);
        mesh.setLocalTransform(local);
        const float s = piece.sizeM;
        switch (piece.shape)
        {
        case Shape::Splinter:
            mesh.addLine({-0.5f * s, 0.0f}, {0.5f * s, 0.0f}, 0.22f * s, colour);
            break;
        case Shape::Shard:
        {
            mesh.addTriangle({-0.3f * s, -0.25f * s}, {0.35f * s, -0.1f * s}, {0.0f, 0.45f * s}, colour);
            break;
        }
        case Shape::Chunk:
        {
            const std::array<sf::Vector2f, 5> points = {
                sf::Vector2f(-0.3f * s, -0.25f * s), sf::Vector2f(0.25f * s, -0.3f * s),
                sf::Vector2f(0.35f * s, 0.1f * s), sf::Vector2f(0.05f * s, 0.3f * s),
                sf::Vector2f(-0.35f * s, 0.1f * s)};
            mesh.addConvex(points, colour);
            break;
        }
        case Shape::Puff:
            mesh.addCircle({0.0f, 0.0f}, s * (0.6f + 0.8f * piece.ageS / piece.lifeS), colour, 12);
            break;
        case Shape::Flash:
            mesh.addCircle({0.0f, 0.0f}, s * (0.3f + 0.7f * std::sqrt(piece.ageS / piece.lifeS)), colour, 32);
            break;
        case Shape::Ring:
            mesh.addRing({0.0f, 0.0f}, s * (0.2f + 0.8f * std::sqrt(piece.ageS / piece.lifeS)), 0.06f * s, colour, 48);
            break;
        case Shape::Smoke:
            mesh.addCircle({0.0f, 0.0f}, s * (0.7f + 0.9f * piece.ageS / piece.lifeS), colour, 14);
            break;
        }
    }
    mesh.resetLocalTransform();
}

} // namespace abalike::app

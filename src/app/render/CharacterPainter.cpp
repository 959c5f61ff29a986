#include "render/CharacterPainter.hpp"

#include "render/AbilityLook.hpp"
#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace abalike::app
{

namespace
{
/// A disc with an outline at least a pixel or so wide.
void outlinedDisc(Mesh& mesh, sf::Vector2f centre, float radius, sf::Color fill, sf::Color outline, float stroke)
{
    mesh.addCircle(centre, radius, outline, 28);
    mesh.addCircle(centre, std::max(radius - stroke, 0.0f), fill, 28);
}

void eye(Mesh& mesh, sf::Vector2f centre, float radius, sf::Vector2f look, float stroke)
{
    outlinedDisc(mesh, centre, radius, palette::kEyeWhite, palette::kPupil, 0.6f * stroke);
    mesh.addCircle(centre + look * radius * 0.35f, radius * 0.48f, palette::kPupil, 14);
}

/// The cap of a circle above the chord at height `chordY`, as a convex polygon.
std::vector<sf::Vector2f> cap(float radius, float chordY)
{
    const float start = std::asin(std::clamp(chordY / radius, -1.0f, 1.0f));
    const float end = std::numbers::pi_v<float> - start;
    std::vector<sf::Vector2f> points;
    constexpr int kSegments = 16;
    for (int i = 0; i <= kSegments; ++i)
    {
        const float a = start + (end - start) * static_cast<float>(i) / kSegments;
        points.emplace_back(radius * std::cos(a), radius * std::sin(a));
    }
    return points;
}
} // namespace

void CharacterPainter::paintBird(Mesh& mesh, const BirdType& bird, float r, float pixelM, BirdMood mood)
{
    const BirdColours colours = birdColours(bird.look);
    const float stroke = std::max(0.06f * r, 1.5f * pixelM);

    // Tail feathers behind the body.
    mesh.addTriangle({-0.7f * r, 0.15f * r}, {-1.45f * r, 0.45f * r}, {-1.3f * r, 0.05f * r}, palette::kPupil);
    mesh.addTriangle({-0.7f * r, 0.0f}, {-1.4f * r, -0.2f * r}, {-1.25f * r, 0.15f * r}, palette::kPupil);
    // Head tuft.
    mesh.addTriangle({-0.15f * r, 0.85f * r}, {0.05f * r, 1.45f * r}, {0.15f * r, 0.9f * r}, colours.outline);
    mesh.addTriangle({-0.35f * r, 0.8f * r}, {-0.3f * r, 1.3f * r}, {-0.05f * r, 0.9f * r}, colours.outline);

    outlinedDisc(mesh, {0.0f, 0.0f}, r, colours.body, colours.outline, stroke);
    mesh.addEllipse({-0.05f * r, -0.42f * r}, 0.62f * r, 0.4f * r, colours.belly, 20);

    abilityLook(bird.abilityName()).decorateBird(mesh, r);

    // Beak: upper and lower half.
    mesh.addTriangle({0.5f * r, -0.02f * r}, {1.22f * r, -0.16f * r}, {0.55f * r, -0.3f * r}, palette::kBeak);
    mesh.addTriangle({0.55f * r, -0.3f * r}, {1.05f * r, -0.26f * r}, {0.55f * r, -0.46f * r}, palette::kBeakDark);

    const float brow = 0.13f * r;
    if (mood == BirdMood::Dazed)
    {
        // Crossed eyes under raised brows, and stars circling the head.
        eye(mesh, {0.2f * r, 0.22f * r}, 0.21f * r, {0.9f, -0.4f}, stroke);
        eye(mesh, {0.62f * r, 0.22f * r}, 0.19f * r, {-0.9f, 0.4f}, stroke);
        mesh.addLine({-0.02f * r, 0.5f * r}, {0.36f * r, 0.6f * r}, brow, colours.brow);
        mesh.addLine({0.46f * r, 0.6f * r}, {0.84f * r, 0.5f * r}, brow, colours.brow);
        for (const sf::Vector2f at : {sf::Vector2f(-0.55f * r, 1.25f * r), sf::Vector2f(0.15f * r, 1.55f * r),
                                      sf::Vector2f(0.85f * r, 1.2f * r)})
            mesh.addStar(at, 0.22f * r, 0.09f * r, palette::kStar);
        return;
    }
    const sf::Vector2f look(1.0f, 0.0f);
    eye(mesh, {0.2f * r, 0.22f * r}, 0.21f * r, look, stroke);
    eye(mesh, {0.62f * r, 0.22f * r}, 0.19f * r, look, stroke);

    // Angry brows slanting down towards the beak.
    mesh.addLine({-0.06f * r, 0.56f * r}, {0.38f * r, 0.36f * r}, brow, colours.brow);
    mesh.addLine({0.44f * r, 0.36f * r}, {0.86f * r, 0.52f * r}, brow, colours.brow);
}

void CharacterPainter::paintPig(Mesh& mesh, float r, bool helmet, float healthFraction, float pixelM)
{
    const float stroke = std::max(0.06f * r, 1.5f * pixelM);
    sf::Color skin = palette::kPig;
    if (healthFraction < 0.33f)
        skin = darken(skin, 0.78f);
    else if (healthFraction < 0.66f)
        skin = darken(skin, 0.9f);

    // Ears first, so the head overlaps them.
    for (const float side : {-1.0f, 1.0f})
    {
        outlinedDisc(mesh, {side * 0.58f * r, 0.78f * r}, 0.24f * r, skin, palette::kPigOutline, stroke);
        mesh.addCircle({side * 0.58f * r, 0.78f * r}, 0.11f * r, palette::kPigOutline, 12);
    }
    outlinedDisc(mesh, {0.0f, 0.0f}, r, skin, palette::kPigOutline, stroke);

    if (healthFraction < 0.66f)
        mesh.addEllipse({0.42f * r, -0.45f * r}, 0.22f * r, 0.16f * r, palette::kBruise, 16);
    if (healthFraction < 0.33f)
    {
        mesh.addEllipse({-0.5f * r, -0.3f * r}, 0.2f * r, 0.15f * r, palette::kBruise, 16);
        mesh.addCircle({-0.42f * r, 0.3f * r}, 0.3f * r, palette::kBruise, 18); // a black eye
    }

    // Eyes either side of the snout.
    eye(mesh, {-0.42f * r, 0.3f * r}, 0.2f * r, {-0.4f, 0.0f}, stroke);
    eye(mesh, {0.42f * r, 0.3f * r}, 0.2f * r, {-0.4f, 0.0f}, stroke);

    // Snout with two nostrils.
    mesh.addEllipse({0.0f, -0.08f * r}, 0.4f * r, 0.3f * r, palette::kPigOutline, 24);
    mesh.addEllipse({0.0f, -0.08f * r}, 0.4f * r - stroke, 0.3f * r - stroke, palette::kPigSnout, 24);
    mesh.addEllipse({-0.14f * r, -0.08f * r}, 0.07f * r, 0.12f * r, palette::kPigNostril, 12);
    mesh.addEllipse({0.14f * r, -0.08f * r}, 0.07f * r, 0.12f * r, palette::kPigNostril, 12);

    // The mouth tells how the pig is doing: a smug grin, a frown, then a wobble.
    const float lip = 0.07f * r;
    if (healthFraction >= 0.66f)
    {
        mesh.addRoundLine({-0.36f * r, -0.5f * r}, {-0.12f * r, -0.6f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({-0.12f * r, -0.6f * r}, {0.12f * r, -0.6f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({0.12f * r, -0.6f * r}, {0.36f * r, -0.5f * r}, lip, palette::kPigOutline);
    }
    else if (healthFraction >= 0.33f)
    {
        mesh.addRoundLine({-0.3f * r, -0.66f * r}, {-0.1f * r, -0.58f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({-0.1f * r, -0.58f * r}, {0.1f * r, -0.58f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({0.1f * r, -0.58f * r}, {0.3f * r, -0.66f * r}, lip, palette::kPigOutline);
    }
    else
    {
        mesh.addRoundLine({-0.32f * r, -0.6f * r}, {-0.16f * r, -0.52f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({-0.16f * r, -0.52f * r}, {0.0f, -0.62f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({0.0f, -0.62f * r}, {0.16f * r, -0.52f * r}, lip, palette::kPigOutline);
        mesh.addRoundLine({0.16f * r, -0.52f * r}, {0.32f * r, -0.6f * r}, lip, palette::kPigOutline);
    }

    if (helmet)
    {
        // A steel cap above the eyes, with a darker rim and a glint.
        const std::vector<sf::Vector2f> outer = cap(1.1f * r, 0.52f * r);
        const std::vector<sf::Vector2f> inner = cap(1.1f * r - stroke, 0.52f * r + stroke);
        mesh.addConvex(outer, palette::kHelmetDark);
        mesh.addConvex(inner, palette::kHelmet);
        mesh.addLine({-0.92f * r, 0.56f * r}, {0.92f * r, 0.56f * r}, 0.12f * r, palette::kHelmetDark);
        mesh.addLine({-0.45f * r, 0.9f * r}, {-0.1f * r, 1.0f * r}, 0.08f * r, sf::Color(220, 222, 230));
    }
}

} // namespace abalike::app

#pragma once

#include "render/Mesh.hpp"

#include <string_view>

namespace abalike::app
{

/// Draws the faces of the game: birds and pigs, centred at the origin of the mesh's local frame (y up,
/// facing +x), so they roll with their bodies.
class CharacterPainter
{
public:
    /// How a bird looks: angry until it hits something, then dazed (crossed eyes, raised brows, stars).
    enum class BirdMood
    {
        Angry,
        Dazed,
    };

    /// A bird of the given type (red, blue, yellow, black, white) with eyes, brows, beak and tail.
    static void paintBird(Mesh& mesh, std::string_view type, float radius, float pixelM,
                          BirdMood mood = BirdMood::Angry);
    /// The white bird's egg: a speckled cream oval the size of its body.
    static void paintEgg(Mesh& mesh, float radius, float pixelM);
    /// A pig; a helmet pig wears a grey cap. Healthy it grins; below 66% health it frowns with a bruise; below 33%
    /// it has a black eye, a second bruise and a wobbly mouth.
    static void paintPig(Mesh& mesh, float radius, bool helmet, float healthFraction, float pixelM);
};

} // namespace abalike::app

#pragma once

#include "render/Mesh.hpp"

#include <abalike/world/Catalog.hpp>

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

    /// A bird in its catalog colours with eyes, brows, beak and tail, and what its ability's look adds (the black
    /// bird's fuse).
    static void paintBird(Mesh& mesh, const BirdType& bird, float radius, float pixelM,
                          BirdMood mood = BirdMood::Angry);
    /// A pig; a helmet pig wears a grey cap. Healthy it grins; below 66% health it frowns with a bruise; below 33%
    /// it has a black eye, a second bruise and a wobbly mouth.
    static void paintPig(Mesh& mesh, float radius, bool helmet, float healthFraction, float pixelM);
};

} // namespace abalike::app

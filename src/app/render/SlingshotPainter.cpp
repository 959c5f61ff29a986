#include "render/SlingshotPainter.hpp"

#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr float kForkBelowPouchM = 0.6f;
constexpr float kTipAbovePouchM = 0.22f;
constexpr float kProngSpreadM = 0.24f;

sf::Vector2f fork(const SlingshotPose& pose)
{
    return {pose.base.x, std::max(pose.pouch.y - kForkBelowPouchM, pose.base.y + 0.2f)};
}

sf::Vector2f backTip(const SlingshotPose& pose)
{
    return {pose.base.x + kProngSpreadM, pose.pouch.y + kTipAbovePouchM};
}

sf::Vector2f frontTip(const SlingshotPose& pose)
{
    return {pose.base.x - kProngSpreadM, pose.pouch.y + kTipAbovePouchM};
}

/// Where the bands hold the bird: on its side away from the launch direction.
sf::Vector2f birdSeat(const SlingshotPose& pose)
{
    const sf::Vector2f bird = *pose.loadedBird;
    sf::Vector2f direction = pose.pouch - bird;
    const float length = std::sqrt(direction.x * direction.x + direction.y * direction.y);
    direction = length > 1e-3f ? direction / length : sf::Vector2f(1.0f, 0.0f);
    return bird - direction * (0.85f * pose.birdRadius);
}

float bandWidth(float pixelM)
{
    return std::max(0.08f, 3.0f * pixelM);
}
} // namespace

void SlingshotPainter::paintBack(Mesh& mesh, const SlingshotPose& pose, float pixelM)
{
    const float trunk = std::max(0.22f, 4.0f * pixelM);
    const float prong = std::max(0.16f, 3.0f * pixelM);
    const sf::Vector2f split = fork(pose);
    mesh.addRoundLine(pose.base, split, trunk + 2.0f * pixelM, palette::kSlingshotDark);
    mesh.addRoundLine(pose.base, split, trunk, palette::kSlingshotWood);
    mesh.addRoundLine(split, backTip(pose), prong + 2.0f * pixelM, palette::kSlingshotDark);
    mesh.addRoundLine(split, backTip(pose), prong, palette::kSlingshotWood);

    if (pose.loadedBird)
    {
        mesh.addLine(backTip(pose) + sf::Vector2f(0.0f, -0.06f), birdSeat(pose), bandWidth(pixelM), palette::kBand);
        return;
    }
    // Empty: the band hangs slack between the prongs.
    const sf::Vector2f sag(pose.base.x, pose.pouch.y + 0.05f);
    const sf::Vector2f band[] = {backTip(pose) + sf::Vector2f(0.0f, -0.06f), sag,
                                 frontTip(pose) + sf::Vector2f(0.0f, -0.06f)};
    mesh.addPolyline(band, bandWidth(pixelM), palette::kBand);
}

void SlingshotPainter::paintFront(Mesh& mesh, const SlingshotPose& pose, float pixelM)
{
    const float prong = std::max(0.16f, 3.0f * pixelM);
    const sf::Vector2f split = fork(pose);
    if (pose.loadedBird)
    {
        const sf::Vector2f seat = birdSeat(pose);
        mesh.addLine(frontTip(pose) + sf::Vector2f(0.0f, -0.06f), seat, bandWidth(pixelM), palette::kBand);
        mesh.addCircle(seat, std::max(0.09f, 3.0f * pixelM), palette::kBand, 12); // the leather pouch
    }
    mesh.addRoundLine(split, frontTip(pose), prong + 2.0f * pixelM, palette::kSlingshotDark);
    mesh.addRoundLine(split, frontTip(pose), prong, palette::kSlingshotWood);
}

} // namespace abalike::app

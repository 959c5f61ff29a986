#include "render/Camera.hpp"

#include "render/CameraFit.hpp"

#include <algorithm>

namespace abalike::app
{

Camera Camera::fitLevel(const LevelDef& level, const Catalog& catalog, sf::Vector2u windowSize)
{
    const CameraView view = fitBox(levelHomeBox(level, catalog), static_cast<float>(level.groundY), windowSize);
    return centredOn(view.centreM, view.pixelsPerMetre, windowSize);
}

Camera Camera::centredOn(sf::Vector2f centreM, float pixelsPerMetre, sf::Vector2u windowSize)
{
    const float ppm = std::max(pixelsPerMetre, 1e-6f);
    const sf::Vector2f halfM(0.5f * static_cast<float>(windowSize.x) / ppm,
                             0.5f * static_cast<float>(windowSize.y) / ppm);
    return Camera({centreM.x - halfM.x, centreM.y + halfM.y}, ppm, windowSize);
}

Camera::Camera(sf::Vector2f worldAtScreenOrigin, float pixelsPerMetre, sf::Vector2u windowSize)
    : m_pixelsPerMetre(pixelsPerMetre), m_windowSize(windowSize)
{
    m_transform.scale(pixelsPerMetre, -pixelsPerMetre).translate(-worldAtScreenOrigin);
    m_inverse = m_transform.getInverse();
    const float widthM = static_cast<float>(windowSize.x) / pixelsPerMetre;
    const float heightM = static_cast<float>(windowSize.y) / pixelsPerMetre;
    m_visible = sf::FloatRect(worldAtScreenOrigin.x, worldAtScreenOrigin.y - heightM, widthM, heightM);
}

} // namespace abalike::app

#include "render/AbilityLook.hpp"
#include "render/Palette.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{

/// The white bird's egg: a speckled cream oval the size of its body.
class EggLook final : public AbilityLook
{
public:
    bool paintBody(Mesh& mesh, const Entity& body, float pixelM) const override
    {
        const auto r = static_cast<float>(0.5 * body.widthM);
        const float stroke = std::max(0.06f * r, 1.5f * pixelM);
        mesh.addEllipse({0.0f, 0.0f}, 0.86f * r, 1.08f * r, palette::kEggOutline, 24);
        mesh.addEllipse({0.0f, 0.0f}, 0.86f * r - stroke, 1.08f * r - stroke, palette::kEgg, 24);
        mesh.addEllipse({-0.3f * r, 0.4f * r}, 0.14f * r, 0.22f * r, sf::Color(255, 255, 255), 12);
        mesh.addCircle({0.25f * r, -0.2f * r}, 0.08f * r, palette::kEggOutline, 8);
        mesh.addCircle({-0.1f * r, -0.5f * r}, 0.06f * r, palette::kEggOutline, 8);
        return true;
    }
};

} // namespace

std::unique_ptr<AbilityLook> makeEggLook()
{
    return std::make_unique<EggLook>();
}

} // namespace abalike::app

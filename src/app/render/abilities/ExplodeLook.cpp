#include "render/AbilityLook.hpp"
#include "render/Palette.hpp"

namespace abalike::app
{

namespace
{

/// A bird that explodes wears a lit fuse; its blast flashes as wide as it reaches (the default effect).
class ExplodeLook final : public AbilityLook
{
public:
    void decorateBird(Mesh& mesh, float r) const override
    {
        mesh.addLine({0.0f, 0.9f * r}, {0.12f * r, 1.35f * r}, 0.12f * r, palette::kHelmet);
        mesh.addCircle({0.14f * r, 1.42f * r}, 0.12f * r, palette::kStar, 10);
    }
};

} // namespace

std::unique_ptr<AbilityLook> makeExplodeLook()
{
    return std::make_unique<ExplodeLook>();
}

} // namespace abalike::app

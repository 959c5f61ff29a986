#include "screens/PlayLayer.hpp"
#include "teach/TeachLayer.hpp"

#include "audio/SoundLayer.hpp"
#include "editor/BirdBodyNotice.hpp"
#include "fx/FxLayer.hpp"

namespace abalike::app
{

std::vector<std::unique_ptr<PlayLayer>> makePlayLayers(App& app)
{
    std::vector<std::unique_ptr<PlayLayer>> layers;
    // Bottom first: layers drawn later are drawn over earlier ones and see input first.
    layers.push_back(std::make_unique<SoundLayer>());
    layers.push_back(std::make_unique<TeachLayer>(app));
    layers.push_back(std::make_unique<BirdBodyNotice>());
    // On top: debris falls in front of the overlays, and score pop-ups are never hidden under a panel.
    layers.push_back(std::make_unique<FxLayer>());
    return layers;
}

} // namespace abalike::app

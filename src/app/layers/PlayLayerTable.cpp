#include "layers/PlayLayerTable.hpp"
#include "shell/AppContext.hpp"

#include "audio/SoundLayer.hpp"
#include "fx/FxLayer.hpp"
#include "teach/BirdBodyNotice.hpp"
#include "teach/TeachLayer.hpp"

namespace abalike::app
{

std::vector<std::unique_ptr<PlayLayer>> makePlayLayers(AppContext& app)
{
    std::vector<std::unique_ptr<PlayLayer>> layers;
    layers.push_back(std::make_unique<SoundLayer>());
    layers.push_back(std::make_unique<TeachLayer>(app));
    layers.push_back(std::make_unique<BirdBodyNotice>());
    layers.push_back(std::make_unique<FxLayer>());
    return layers;
}

} // namespace abalike::app

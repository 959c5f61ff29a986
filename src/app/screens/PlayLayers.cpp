#include "screens/PlayLayer.hpp"

namespace abalike::app
{

std::vector<std::unique_ptr<PlayLayer>> makePlayLayers(App& app)
{
    (void)app;
    std::vector<std::unique_ptr<PlayLayer>> layers;
    // Bottom first: layers drawn later are drawn over earlier ones and see input first.
    return layers;
}

} // namespace abalike::app

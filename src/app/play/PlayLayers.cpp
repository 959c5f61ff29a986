#include "play/PlayLayer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace abalike::app
{

namespace
{

struct Registered
{
    int order = 0;
    std::string name;
    PlayLayerFactory make;
};

std::vector<Registered>& registry()
{
    // A function-local static: layers register from their own files' static initialisers, in any order.
    static std::vector<Registered> layers;
    return layers;
}

} // namespace

PlayLayerRegistrar::PlayLayerRegistrar(int order, std::string name, PlayLayerFactory make)
{
    std::vector<Registered>& layers = registry();
    for (const Registered& layer : layers)
        if (layer.order == order || layer.name == name)
            throw std::logic_error("play layer \"" + name + "\" registered twice or at a taken order");
    layers.push_back({order, std::move(name), std::move(make)});
    std::sort(layers.begin(), layers.end(), [](const Registered& a, const Registered& b) { return a.order < b.order; });
}

std::vector<std::unique_ptr<PlayLayer>> makePlayLayers(App& app)
{
    std::vector<std::unique_ptr<PlayLayer>> layers;
    for (const Registered& layer : registry())
        layers.push_back(layer.make(app));
    return layers;
}

} // namespace abalike::app

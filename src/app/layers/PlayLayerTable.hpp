#pragma once

#include "play/PlayLayer.hpp"

#include <memory>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The layers every play screen (and the editor's play test) gets, bottom first: drawn first, offered input last.
/// An explicit table (PlayLayerTable.cpp), so linking the app in any way keeps every layer.
std::vector<std::unique_ptr<PlayLayer>> makePlayLayers(AppContext& app);

} // namespace abalike::app

#pragma once

#include <string>

struct _cairo_surface;

namespace abalike::app
{

/// Writes a cairo image surface to a PNG file. Throws PlotError naming `what` and the path when it cannot.
void writeSurfacePng(_cairo_surface* surface, const std::string& path, const std::string& what);

} // namespace abalike::app

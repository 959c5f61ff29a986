#pragma once

namespace abalike::app
{

/// Where one frame's wall time went (`bench frames`). On software GL the pixels are filled when the frame is
/// shown, so `displayS` holds the rasterizer's work and `drawS` the geometry and the draw calls.
struct FrameTimes
{
    double physicsS = 0.0; ///< the fixed physics steps of the frame
    double previewS = 0.0; ///< the RK4 preview, when the aim changed
    double updateS = 0.0;  ///< events and the rest of the frame update (camera, layers), preview excluded
    double drawS = 0.0;    ///< building and submitting every layer
    double displayS = 0.0; ///< showing the frame: the rasterizer's fill on software GL
    double totalS = 0.0;   ///< the whole frame by the wall clock
};

} // namespace abalike::app

#pragma once

#include "shell/FrameLayout.hpp"
#include "shell/FrameTimes.hpp"

namespace abalike::app
{

/// Watches the frame loop from outside the game: `bench frames` times frames, the layout walk lays them out without
/// drawing a pixel. The loop calls it at fixed points; nothing in the game depends on it (AppOptions::observer).
class FrameObserver
{
public:
    virtual ~FrameObserver() = default;

    /// Once, with the seconds from opening the first screen (loading its level) to its first frame.
    virtual void firstFrame(double loadS) { (void)loadS; }
    /// After every frame but a run's last, with where its wall time went.
    virtual void frameTimed(const FrameTimes& times) { (void)times; }
    /// 0: frames are drawn. N > 0: no pixel is drawn or shown, and every Nth frame (and the last) is laid out and
    /// handed to laidOut; laying a frame out costs a fraction of drawing it, so a test can walk every level at every
    /// text size and window.
    virtual int layoutEvery() const { return 0; }
    virtual void laidOut(const FrameLayout& frame) { (void)frame; }
};

} // namespace abalike::app

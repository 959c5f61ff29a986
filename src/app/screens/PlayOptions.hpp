#pragma once

#include <abalike/game/GameSession.hpp>

#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// What `abalike play` was asked to do.
struct PlayOptions
{
    std::vector<std::string> levelPaths; ///< levels to play in order (the campaign when none was given)
    std::optional<int> frames;           ///< exit after this many frames; the clock then advances 1/60 s per frame
    std::string screenshotPath;          ///< save the last frame here (PNG) when not empty
    std::vector<ScriptedShot> shots;     ///< fired in order whenever a bird is ready
    unsigned width = 1280;
    unsigned height = 720;
};

/// Opens the window and plays. Returns the process exit code.
int runPlay(const PlayOptions& options);

} // namespace abalike::app

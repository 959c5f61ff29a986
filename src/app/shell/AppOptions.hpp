#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/save/Settings.hpp>
#include <abalike/script/InputScript.hpp>

#include "shell/FrameObserver.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sf
{
class RenderWindow;
}

namespace abalike::app
{

class AppContext;
class Screen;

/// What `abalike play` was asked to do.
struct AppOptions
{
    std::string levelPath;           ///< play this level file directly; empty: the campaign (title screen)
    std::optional<LevelDef> level;   ///< that level, loaded and checked before the window opens
    std::string campaignPath;        ///< the campaign manifest (levels/campaign.json)
    std::optional<int> frames;       ///< exit after this many frames; the clock then advances 1/60 s per frame
    std::string screenshotPath;      ///< save the last frame here (PNG) when not empty
    std::vector<ScriptedShot> shots; ///< fired in order whenever a bird is ready
    InputScript script;              ///< timed input events (`--script`), checked before the window opens
    bool hasScript = false;
    std::string tracePath;         ///< write what happens (screens, levels, shots) as JSON lines here
    std::optional<unsigned> width; ///< `--size` wins over the saved window size
    std::optional<unsigned> height;
    std::optional<Wording> wording;           ///< `--wording` wins over the saved setting for this run
    std::optional<PlayMode> mode;             ///< `--mode` wins over the saved setting for this run
    bool endless = false;                     ///< `play --endless`: straight into the endless mode
    std::optional<std::uint64_t> endlessSeed; ///< `--seed`: the first generated level's; none: from the clock

    /// Watches the frame loop (`bench frames`, the layout walk); null for a plain run.
    FrameObserver* observer = nullptr;
    /// Plays in this open window instead of opening one, and leaves it open (`--size` is then its size): the layout
    /// walk keeps one window, and one OpenGL context, for each size it walks rather than start a new one per run.
    sf::RenderWindow* window = nullptr;

    /// The screen the run opens with (the title, a level, the editor): the layers above the shell choose it
    /// (screens/GameScreens.hpp; `abalike edit` opens the editor this way).
    std::function<std::unique_ptr<Screen>(AppContext&)> firstScreen;
    /// The help screen F1 and '?' open over any screen (none: the keys do nothing).
    std::function<std::unique_ptr<Screen>(AppContext&)> helpScreen;

    /// A scripted run (frames, input script or shots) reads the player's files but never writes them.
    bool scripted() const { return frames.has_value() || hasScript || !shots.empty(); }
};

} // namespace abalike::app

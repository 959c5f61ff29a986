#pragma once

#include "shell/AppOptions.hpp"
#include "shell/Screen.hpp"

#include <memory>

namespace abalike::app
{

class AppContext;

/// The game's opening screen for a run: the level given on the command line (its place in the campaign found, so
/// "next" follows the campaign), the campaign's first level for scripted shots without a level, else the title.
std::unique_ptr<Screen> openingScreen(AppContext& app);

/// Gives a run the game's screens: the opening screen (unless the command chose another, as `edit` does) and the
/// help screen.
void useGameScreens(AppOptions& options);

} // namespace abalike::app

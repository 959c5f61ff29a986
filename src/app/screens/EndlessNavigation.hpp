#pragma once

#include <memory>

namespace abalike::app
{

class AppContext;
class Screen;

/// The endless run's next level as a play screen when one is ready; null when not.
std::unique_ptr<Screen> endlessLevelScreen(AppContext& app);

/// The endless run's next level as a screen: the level when one is ready, else the card that waits for it.
std::unique_ptr<Screen> nextEndlessScreen(AppContext& app);

/// Plays the endless run's next level (or waits for it) over the title screen, leaving every other screen.
void playNextEndlessLevel(AppContext& app);

} // namespace abalike::app

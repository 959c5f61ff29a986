#pragma once

#include <cstddef>

namespace abalike::app
{

class App;

/// Back to the title screen, leaving every other screen.
void openTitle(App& app);
/// The level select, over the title (so Esc goes back to the title), leaving every other screen.
void openLevelSelect(App& app);
/// The campaign level a player continues with: the first unlocked level without a star, else the last unlocked one.
std::size_t continueLevel(const App& app);
/// Plays campaign level `index` over the screens already there.
void playCampaignLevel(App& app, std::size_t index);

} // namespace abalike::app

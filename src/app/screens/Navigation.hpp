#pragma once

#include <cstddef>

namespace abalike::app
{

class AppContext;

/// Back to the title screen, leaving every other screen.
void openTitle(AppContext& app);
/// The level select, over the title (so Esc goes back to the title), leaving every other screen.
void openLevelSelect(AppContext& app);
/// The campaign level a player continues with: the first unlocked level without a star, else the last unlocked one.
std::size_t continueLevel(const AppContext& app);
/// Plays campaign level `index` over the screens already there.
void playCampaignLevel(AppContext& app, std::size_t index);

} // namespace abalike::app

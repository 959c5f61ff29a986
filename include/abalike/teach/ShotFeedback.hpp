#pragma once

#include <abalike/game/GameSession.hpp>
#include <string>
#include <vector>

namespace abalike
{

/// One or two sentences about a finished shot, with its real numbers: how far the wind moved the landing point, how
/// much energy drag took and how far the launch would have flown in vacuum, how much momentum went into the
/// structure, or in vacuum what the best angle for this speed would have been. Most telling first.
std::vector<std::string> shotFeedback(const LevelDef& level, const Catalog& catalog, const ShotRecord& shot,
                                      double physicsDtS = 1.0 / 60.0);

/// The first sentence's gist in one short, whole sentence (about 60 characters), for a card short of room: "The bird
/// broke a wood block and flew on." Empty when there is no feedback.
std::string shotSummary(const LevelDef& level, const Catalog& catalog, const ShotRecord& shot,
                        double physicsDtS = 1.0 / 60.0);

} // namespace abalike

#pragma once

#include <abalike/edit/SceneObject.hpp>

#include <optional>
#include <string>
#include <vector>

namespace abalike
{

class Catalog;

/// Why a block or pig the editor just placed, dropped, pasted or moved does not land on what is under it, in the
/// words `abalike check` uses for it: "block 3 floats 32.0 cm above block 1 (wood), more than the 10.0 cm the
/// editor pulls a body down: it falls when the level starts; drag it down onto block 1 (wood)". reachM: how far
/// the editor's snapping pulls a body onto the surface below (SnapSettings::surfaceReachM, or 0 with surfaces off).
/// None when every one of them rests on something (within a millimetre) or is terrain or the slingshot; with
/// several floating, the first and how many more.
std::optional<std::string> whyNotLanded(const LevelDef& level, const Catalog& catalog,
                                        const std::vector<ObjectRef>& objects, double reachM);

} // namespace abalike

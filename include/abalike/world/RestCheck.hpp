#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/GameWorld.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// How far one block or pig moved while its level was left alone.
struct BodyRest
{
    EntityKind kind = EntityKind::Block;
    int defIndex = -1;
    std::string typeName;
    double maxDisplacementM = 0.0;   ///< largest move of any corner of its bounding box (centre for circles)
    double finalDisplacementM = 0.0; ///< the same at the end of the check
    bool damaged = false;
    bool destroyed = false;
    /// When it started: the first time it moved more than kStartedMovingM or took damage (s); none if never. The
    /// first bodies to start are what makes a level fail; the ones that start later, touching them, follow.
    std::optional<double> startedS;

    static constexpr double kStartedMovingM = 0.001;
};

/// The largest mass ratio of a body resting on a lighter one (Box2D's stacking degrades past 10:1 heavy on light;
/// a light body on a heavy one is no trouble).
struct MassRatio
{
    double ratio = 1.0;  ///< upper mass / lower mass; 1 when nothing rests on something lighter
    std::string heavier; ///< the upper body, e.g. "block 3 (stone)"
    std::string lighter; ///< the body under it
};

/// What a level did when nothing was shot at it: the stability check designers rely on.
struct RestReport
{
    double seconds = 0.0;
    double toleranceM = 0.005;
    std::vector<BodyRest> bodies;
    double maxDisplacementM = 0.0;
    double maxFinalDisplacementM = 0.0; ///< largest displacement at the end (the max above may be a transient)
    int worstBody = -1;                 ///< index into bodies of the one that moved most
    int damagedBodies = 0;
    int destroyedBodies = 0;
    bool settled = false;     ///< every body asleep at the end
    MassRatio worstMassRatio; ///< heaviest body resting on a lighter one
    int stackDepth = 0;       ///< the most bodies resting on each other (GameWorld::stackDepth)
    int stackSubsteps = 1;    ///< Box2D sub-steps per step the world gave the level for it

    /// Nothing moved more than the tolerance and nothing took damage.
    bool passed() const { return maxDisplacementM <= toleranceM && damagedBodies == 0 && destroyedBodies == 0; }
    /// One line: "stands after 10 s: max move 0.40 mm (block 3, wood) of 5 mm allowed, no damage, ...". A level
    /// that does not stand and has a stack at least kDeepStack bodies deep also gets what to change.
    std::string summary() const;

    /// From this depth on, a failed rest check names the stack depth as the likely cause.
    static constexpr int kDeepStack = 8;
};

/// Leaves a level alone for the given time and reports how far things moved and whether anything took damage.
RestReport checkRest(const LevelDef& level, const Catalog& catalog = Catalog::builtin(), double seconds = 10.0,
                     const WorldSettings& settings = {}, double toleranceM = 0.005);

/// The worst heavy-on-light mass ratio over dynamic bodies resting on each other in the world as it is now.
MassRatio worstStackMassRatio(const GameWorld& world);

} // namespace abalike

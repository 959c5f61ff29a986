#pragma once

namespace abalike
{

/// Box2D settings of a world; the defaults were chosen by measurement (docs/world-physics.md, "Iterations").
struct WorldSettings
{
    double dtS = 1.0 / 60.0;
    int velocityIterations = 8;
    int positionIterations = 3;
    /// A step is split into up to this many Box2D sub-steps so that no body moves more than 90 % of
    /// b2_maxTranslation (2 m) per sub-step; Box2D would otherwise silently cap speeds at 2 m / dt (120 m/s at
    /// 60 Hz). 1 turns sub-stepping off.
    int maxSubsteps = 8;
    bool allowSleep = true;
    /// Velocity iterations of the very first step. Box2D warm-starts each step from the last step's contact
    /// impulses; a level starts with none, and with 8 iterations the top of a 20-block tower falls 10 cm before
    /// the impulses build up. Solving the first step well makes them right from the start (measured in
    /// docs/world-physics.md). kAutoSettle: 5 x depth^2 (at least 2000, at most 10 000), depth being the most
    /// bodies stacked on each other, because Gauss-Seidel needs about depth^2 sweeps to carry the load of the top
    /// body down to the ground; 0: no settle step; more: that many.
    int settleIterations = kAutoSettle;
    /// Box2D sub-steps per step for the level's stacks: ceil(depth / stackDepthPerSubstep), at most
    /// maxStackSubsteps, depth being the most bodies resting on each other (stackDepth()). Sequential impulses
    /// hold a deep stack only approximately; the error grows with depth and shrinks with the sub-step, and a tall
    /// column under an off-centre load leans a little more every step unless the sub-step is short enough
    /// (docs/world-physics.md, "Walls and mixed towers"). 1 turns it off.
    int stackDepthPerSubstep = 5;
    int maxStackSubsteps = 4;
    /// Corners of polygon cores are cut by this much (m) so that blocks meeting only corner to corner, such as
    /// diagonal neighbours in a wall, do not touch (Skin.hpp); 0 turns it off.
    double cornerChamferM = 0.003;
    /// A contact between two bodies (birds aside) acts only once their designed surfaces are closer than this (m).
    /// Box2D makes every contact within its 1 cm skin rigid, which would let a pig near the edge of a block lean
    /// on the rounded corner of the next one, 2 mm away; negative turns it off.
    double contactGapM = 0.001;
    /// Rolling resistance for pigs and round blocks (the catalog's "rolling" coefficient); false turns it off.
    bool rollingResistance = true;
    /// Break-through (Damage::refundBreakingContacts): a body that breaks absorbs only its remaining strength and
    /// whatever struck it keeps the rest of its momentum. false keeps Box2D's impulse as solved, as if the broken
    /// body had been unbreakable for that step (the rule before; tests and `bench feel` compare the two).
    bool breakThrough = true;
    /// A body that breaks yields instead of holding for the rest of its step (Damage::refundBreakingContacts): what
    /// struck it keeps at most the part of the contact impulse that stopped its approach (a block that fails at its
    /// peak load has nothing left to spring back with: no restitution), and friction in the same share as the normal
    /// impulse (Coulomb's bound: friction cannot exceed mu times the normal impulse the body actually held). false
    /// keeps the restitution and the whole friction impulse as Box2D solved them (the rule before issue 37; `bench
    /// feel` compares the two). Only with breakThrough.
    bool breakingBodyYields = true;
    /// A block that breaks hands the momentum it took in its last step to the bodies it was pushing (by their
    /// contact impulses, at the contact points) instead of taking it away as debris: momentum is conserved through a
    /// break, and a tower hit high tips over (Damage::handOnMomentum). false deletes it with the block (the rule
    /// before; `bench feel` compares the two).
    bool handOnMomentum = true;
    /// Reuse settle steps (SettleCache): a world whose bodies and settings match one settled before starts from its
    /// state. Either way the settled state passes through the same restore, so results do not depend on the cache;
    /// false solves the settle step in place as Box2D leaves it (benchmarks that time it or compare with raw Box2D).
    bool settleCache = true;

    static constexpr int kAutoSettle = -1;
};

} // namespace abalike

#pragma once

#include <atomic>
#include <vector>

namespace abalike
{

class WorldBodies;

/// How the world steps: the level's stack depth and the Box2D sub-steps it needs (WorldSettings), the settle
/// step's iterations, Box2D's own steps with rolling resistance, and whether the world is calm.
class WorldStepper
{
public:
    /// Measures the level's stacks in the world as built.
    explicit WorldStepper(WorldBodies& bodies);

    /// The most bodies resting on each other at the start (1 for a block on the ground).
    int stackDepth() const { return m_stackDepth; }
    int settleIterations() const { return m_settleIterations; }
    /// Box2D sub-steps a step takes for the level's stacks at the start.
    int stackSubsteps() const { return m_stackSubsteps; }
    /// The same for the stacks still at rest now (see GameWorld::restingStackSubsteps).
    int restingStackSubsteps() const;
    /// Sub-steps taken by the last step.
    int lastSubsteps() const { return m_lastSubsteps; }
    /// See GameWorld::substepsFor and maxSpeedMps.
    int substepsFor(double speedMps) const;
    double maxSpeedMps() const;

    /// Plans the coming step's sub-steps: the settle step (the first) for every stack of the level, later steps for
    /// the stacks still at rest and the fastest awake body.
    void planStep(bool settle);
    /// Takes the planned sub-steps in Box2D (the settle step's iterations when settle), with rolling resistance.
    void stepBox2d(bool settle);
    /// Sub-steps of the settle step done so far, safe to read from another thread.
    int settleSubstepsDone() const { return m_settleSubstepsDone.load(std::memory_order_relaxed); }
    void markSettleDone() { m_settleSubstepsDone.store(m_lastSubsteps, std::memory_order_relaxed); }

    /// After each step: whether any block or pig moved (GameWorld::isCalm).
    void updateCalm();
    bool isCalm() const;

private:
    /// The most bodies resting on each other (only awake, unmoving ones with restingOnly), counted up to cap.
    int deepestStack(bool restingOnly, int cap) const;
    int stackSubstepsFor(int depth) const;
    int substepCount() const;

    WorldBodies& m_bodies;
    int m_stackDepth = 0;
    int m_settleIterations = 0;
    int m_stackSubsteps = 1;
    int m_restingStackSubsteps = 1; ///< restingStackSubsteps() at the start of the current step
    int m_lastSubsteps = 1;
    std::atomic<int> m_settleSubstepsDone{0};
    double m_calmSinceS = 0.0; ///< < 0 while something moves
    /// deepestStack's breadth-first search, kept between steps so that a step allocates nothing for it.
    mutable std::vector<int> m_stackDepthOf;
    mutable std::vector<int> m_stackFrontier;
    mutable std::vector<int> m_stackNext;
};

} // namespace abalike

#pragma once

#include <abalike/world/Entity.hpp>
#include <array>
#include <box2d/box2d.h>
#include <unordered_map>
#include <vector>

namespace abalike
{

/// Every linear impulse Box2D gives each body during one world step, as vectors: contact impulses (of the regular
/// and the time-of-impact solves) and gravity over the sub-steps in which Box2D integrated the body. The first
/// impact's momentum balance is read from it (FirstImpact::balance), so it runs only while the bird flies free.
class ImpulseLedger
{
public:
    /// What one body received during the step (N s = kg m/s).
    struct Account
    {
        Vec2 contacts{}; ///< from every contact
        Vec2 fromBird{}; ///< the part from contacts with the watched bird
        Vec2 gravity{};  ///< weight x the time Box2D integrated the body
    };

    bool active() const { return m_active; }
    /// Starts a step's ledger (active) or stops keeping one.
    void startStep(bool active);
    /// Before each Box2D sub-step: which bodies are awake and where every body is now.
    void beginSubstep(const std::vector<Entity>& entities);
    /// After it: gravity for each body Box2D integrated in it (h: the sub-step's time, s).
    void endSubstep(const std::vector<Entity>& entities, const b2Vec2& gravity, float h);

    void preSolve(b2Contact* contact);
    void postSolve(b2Contact* contact, const b2ContactImpulse* impulse, const b2Body* bird);

    /// What entity index received during the step (zeros when it received nothing).
    Account account(int index) const;

private:
    b2Vec2 normalOf(b2Contact* contact) const;
    Account& accountOf(int index);

    bool m_active = false;
    std::vector<Account> m_accounts;
    std::vector<b2Transform> m_startTransforms; ///< per entity, at the sub-step's start: what the solver starts from
    std::vector<char> m_awakeAtStart;
    std::vector<char> m_solvedInIsland; ///< reached by the sub-step's regular solve (so Box2D integrated it)
    /// Normals of the contacts updated in this sub-step that may be solved at a time of impact (a bullet or a
    /// static body on one side), as Box2D's solver saw them: by then the bodies may have moved on.
    std::unordered_map<const b2Contact*, b2Vec2> m_normals;
};

} // namespace abalike

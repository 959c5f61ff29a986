#pragma once

#include <abalike/util/Vec2.hpp>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

enum class EntityKind; // GameWorld.hpp

/// A body's velocity at one moment: linear (m/s) and angular (rad/s, counter-clockwise).
struct BodyVelocity
{
    double vx = 0.0;
    double vy = 0.0;
    double omegaRadPerS = 0.0;
};

/// The linear impulses (N s = kg m/s, as x and y) that bird and body received in the step of their first impact
/// besides each other's momentum: with the two changes of momentum they add to zero (FirstImpact::balanceResidual).
struct ImpactBalance
{
    Vec2 pushOnBody{};        ///< from the bird through their contact (the bird got the opposite)
    Vec2 supports{};          ///< on the body from all else it touches: the ground, blocks, neighbours
    Vec2 birdOtherContacts{}; ///< on the bird from anything else it touched in that step
    /// Weight over the time Box2D integrated each body: the struck body's. The bird's weight and drag over the step
    /// are already in the velocity it starts the step with (the flight model's chord), so they add nothing here.
    Vec2 gravity{};
    /// What the break rule moved after the solver: the impulse given back to the bird and to the body's other
    /// partners when it broke, and momentum a breaking block handed on to the bird (0 when nothing broke).
    Vec2 breakThrough{};
};

/// Another body the bird pushed in the step of its first impact: a second block, a pig, the ground.
struct ImpactPartner
{
    EntityKind kind{};
    int index = -1;   ///< index in the level's blocks, pigs or terrain (-1 for the ground)
    std::string type; ///< material, pig type, "ground" or "terrain"
    Vec2 impulse{};   ///< the push on it from the bird (N s); the bird got the opposite
};

/// The launched bird's first contact with a block or a pig, from Box2D's own velocities: "before" is the start of the
/// world step in which the contact began, "after" the end of that step.
struct FirstImpact
{
    double tS = 0.0; ///< time since launch of the first touch
    EntityKind bodyKind{};
    int bodyIndex = -1;   ///< index in the level's blocks or pigs
    std::string bodyType; ///< material or pig type
    double birdMassKg = 0.0;
    double birdInertiaKgM2 = 0.0; ///< about the centre of mass
    double bodyMassKg = 0.0;
    double bodyInertiaKgM2 = 0.0;
    BodyVelocity birdBefore;
    BodyVelocity birdAfter;
    BodyVelocity bodyBefore;
    BodyVelocity bodyAfter;
    Vec2 birdCentre{};             ///< the bird's centre when it touched (m)
    Vec2 bodyCentre{};             ///< the body's centre of mass then
    Vec2 normal{};                 ///< unit contact normal, from the bird into the body
    Vec2 point{};                  ///< where they touched (m)
    double damageNs = 0.0;         ///< impulse the body took as damage during that step (N s)
    double strengthBeforeNs = 0.0; ///< what the body could still absorb when the step began (N s)
    bool broke = false;            ///< the body broke (or the pig was defeated) in that step
    ImpactBalance balance;
    /// Every other body the bird pushed in that step, by entity order.
    std::vector<ImpactPartner> partners;
    /// When the body broke: what of its momentum it handed on to the bodies it was pushing (N s); the rest left with
    /// its splinters. Zero when it held.
    Vec2 handedOn{};

    /// Change of the bird's and of the body's momentum over the step (after minus before, kg m/s).
    Vec2 birdChange() const;
    /// The impulse bird and body exchanged: what the bird gave the body, the body gave the bird the opposite (N s).
    /// The bird's change less what everything else it touched gave it: the solver's push less what the break rule
    /// gave back when the body broke, so it never exceeds what a body that breaks can push back.
    Vec2 exchanged() const;
    Vec2 bodyChange() const;
    /// The two changes less every impulse of the balance: zero but for Box2D's float rounding.
    Vec2 balanceResidual() const;

    /// Linear momentum of bird and body together (kg m/s).
    Vec2 momentumBefore() const;
    Vec2 momentumAfter() const;
    /// Kinetic energy of bird and body together, translation and rotation (J).
    double kineticBeforeJ() const;
    double kineticAfterJ() const;
    /// Coefficient of restitution of the impact: the speed at which the contact points separate along the normal
    /// after the step over the speed at which they closed before it; nullopt if they were not closing.
    std::optional<double> restitution() const;
};

} // namespace abalike

#pragma once

#include <abalike/world/FirstImpact.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

class Catalog;

/// The bird's first impact told as physics (issue 58): the impulse bird and body exchanged, equal and opposite;
/// every other body the bird pushed in that step by more than kNamedImpulseNs, with its own impulse; the bird's
/// change of momentum, which is minus their sum; and apart from them the damage, "X of Y N·s". The solver's step
/// impulse and the break rule's refund are bookkeeping and stay out of it.
struct ImpactAccount
{
    /// A push smaller than this is not named (its share of the sum is below the sentences' rounding).
    static constexpr double kNamedImpulseNs = 1.0;

    struct Partner
    {
        std::string name; ///< "the ground", "a stone block", "the small pig"
        Vec2 impulse{};   ///< on it, from the bird (N s)
    };

    std::string bodyName; ///< what the bird struck, as a sentence names it: "a wood block", "the small pig"
    bool bodyIsPig = false;
    Vec2 exchanged{};              ///< on the struck body, from the bird; the bird got the opposite (N s)
    std::vector<Partner> partners; ///< the other bodies pushed by more than kNamedImpulseNs, the largest first
    Vec2 unnamed{};                ///< what the bird gave everything else, each under kNamedImpulseNs
    Vec2 birdChange{};             ///< = −(exchanged + partners + unnamed)
    double carriedBefore = 0.0;    ///< the bird's momentum, kg m/s
    double carriedAfter = 0.0;
    bool birdKeptDirection = false; ///< still moving the same way along x after the step
    double damageNs = 0.0;          ///< impulse the body took as damage in that step (every push on it counts)
    double strengthNs = 0.0;        ///< what it could still take when the step began
    bool broke = false;
    Vec2 handedOn{};                  ///< of a broken block's momentum: what went on to the bodies it pushed
    Vec2 withSplinters{};             ///< and what left with its splinters
    std::optional<double> bounciness; ///< separating / closing speed; only when nothing broke (else nothing rebounds)

    /// The damage reached what the body could still take.
    bool tookAll() const { return broke || damageNs >= strengthNs; }
};

ImpactAccount accountImpact(const FirstImpact& impact, const Catalog& catalog);

/// "45 of the 50 N·s" with as many decimals (up to two) as it takes to tell two different values apart: a block that
/// took 59.96 of its 60 N·s is never said to have taken "60 of the 60".
std::string damageOfStrength(double damageNs, double strengthNs);

/// The after-shot sentence of an impact: what was exchanged, who else was pushed, how the bird's momentum changed,
/// and the damage; where a broken block's momentum went.
std::string impactSentence(const ImpactAccount& account);

} // namespace abalike

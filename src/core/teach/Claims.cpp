#include "design/ParallelFor.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/Claims.hpp>
#include <abalike/teach/TextValues.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace abalike
{

namespace
{

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && text.front() == ' ')
        text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ')
        text.remove_suffix(1);
    return text;
}

std::string shown(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

bool within(double x, const std::array<double, 2>& range)
{
    return x >= range[0] && x <= range[1];
}

/// Whether one aim defeats a pig the outcome names, by a block it names.
bool aimDoesIt(const OutcomeClaimDef& outcome, const LevelDef& level, const Catalog& catalog, double angleDeg,
               double speedMps)
{
    const std::unique_ptr<GameSession> session = simulateShots(level, {{angleDeg, speedMps}}, catalog);
    // The shot's own window ends when the next bird is ready; a tower may still be falling onto the next.
    while (!session->finished() && session->timeSinceLaunch() < kOutcomeWatchS)
        session->step();
    for (const DestroyedEvent& event : session->defeats())
    {
        if (event.kind != EntityKind::Pig || event.index < 0 ||
            !within(level.pigs[static_cast<std::size_t>(event.index)].x, outcome.pigX))
            continue;
        if (!outcome.byBlockX)
            return true;
        if (event.cause.kind == CauseKind::Block && event.cause.index >= 0 &&
            within(level.blocks[static_cast<std::size_t>(event.cause.index)].x, *outcome.byBlockX))
            return true;
    }
    return false;
}

std::string rangeText(const std::array<double, 2>& range)
{
    return shown(range[0]) + " to " + shown(range[1]) + " m";
}

/// The level's first bird, which outcome and reach claims shoot, and its speed at full pull.
struct FirstBird
{
    std::string name;
    double fullPullMps = 0.0;
};

std::optional<FirstBird> firstBird(const LevelDef& level, const Catalog& catalog)
{
    const Catalog own = levelCatalog(level, catalog);
    const BirdType* bird = level.birds.empty() ? nullptr : own.findBird(level.birds.front());
    if (bird == nullptr)
        return std::nullopt;
    return FirstBird{bird->name, maxLaunchSpeed(level, *bird, own)};
}

ClaimResult noBirdToShoot()
{
    ClaimResult result;
    result.message = "cannot be computed: the level has no bird to shoot";
    return result;
}

ClaimResult evaluateOutcome(const OutcomeClaimDef& outcome, const LevelDef& level, const Catalog& catalog)
{
    const std::optional<FirstBird> first = firstBird(level, catalog);
    if (!first)
        return noBirdToShoot();
    ClaimResult result;
    const double fastest = first->fullPullMps;
    try
    {
        for (const double da : {-kOutcomeFanAngleStepDeg, 0.0, kOutcomeFanAngleStepDeg})
            for (const double dv : {-kOutcomeFanSpeedStepMps, 0.0, kOutcomeFanSpeedStepMps})
                if (aimDoesIt(outcome, level, catalog, outcome.angleDeg + da,
                              std::clamp(outcome.speedMps + dv, 0.0, fastest)))
                    ++result.aimsThatDo;
    }
    catch (const LaunchError& e)
    {
        result.message = std::string("cannot be computed: ") + e.what();
        return result;
    }
    result.holds = result.aimsThatDo >= outcome.inAtLeast;
    result.left = result.aimsThatDo;
    result.right = outcome.inAtLeast;
    result.message = "a pig at x " + rangeText(outcome.pigX) + " falls" +
                     (outcome.byBlockX ? " to a block from x " + rangeText(*outcome.byBlockX) : std::string()) +
                     " in " + std::to_string(result.aimsThatDo) + " of the " + std::to_string(kOutcomeFanAims) +
                     " aims around " + shown(outcome.angleDeg) + "\u00B0, " + shown(outcome.speedMps) +
                     " m/s (the claim needs " + std::to_string(outcome.inAtLeast) + ")";
    return result;
}

/// Whether the bird's flight itself reaches a pig the claim names: its first contact is that pig (not a roll or a
/// bounce off the ground or a block on to it).
bool flightReachesPig(const ReachClaimDef& reach, const LevelDef& level, const Catalog& catalog, double angleDeg,
                      double speedMps)
{
    const std::unique_ptr<GameSession> session = simulateShots(level, {{angleDeg, speedMps}}, catalog);
    const ShotRecord& shot = session->shots().at(0);
    while (!shot.actualContact && !session->finished() && session->timeSinceLaunch() < kOutcomeWatchS)
        session->step();
    return shot.firstTouched == EntityKind::Pig && shot.impact && shot.impact->bodyIndex >= 0 &&
           within(level.pigs.at(static_cast<std::size_t>(shot.impact->bodyIndex)).x, reach.pigX);
}

ClaimResult evaluateReach(const ReachClaimDef& reach, const LevelDef& level, const Catalog& catalog)
{
    const std::optional<FirstBird> first = firstBird(level, catalog);
    if (!first)
        return noBirdToShoot();
    ClaimResult result;
    const double fastest = first->fullPullMps;
    const auto aims = static_cast<std::size_t>(90.0 / kReachAnglesStepDeg);
    std::vector<char> reached(aims, 0);
    double best = 0.0;
    try
    {
        best = evaluateExpression("best_angle:" + first->name, level, catalog);
        parallelFor(
            aims, workerCount(0),
            [&](std::size_t i) {
                reached[i] =
                    flightReachesPig(reach, level, catalog, static_cast<double>(i) * kReachAnglesStepDeg, fastest);
            },
            [](std::size_t) {});
    }
    catch (const std::exception& e)
    {
        result.message = std::string("cannot be computed: ") + e.what();
        return result;
    }
    const auto angleOf = [](std::size_t i)
    {
        return static_cast<double>(i) * kReachAnglesStepDeg;
    };
    const auto nearest = static_cast<std::size_t>(std::lround(best / kReachAnglesStepDeg));
    std::optional<std::size_t> lowest;
    std::optional<std::size_t> highest;
    int outside = 0;
    for (std::size_t i = 0; i < aims; ++i)
        if (reached[i] != 0)
        {
            lowest = lowest.value_or(i);
            highest = i;
            outside += std::abs(angleOf(i) - best) > reach.withinDeg ? 1 : 0;
        }
    const bool bestReaches = nearest < aims && reached[nearest] != 0;
    result.holds = bestReaches && outside == 0;
    result.left = outside;
    result.right = 0.0;
    const std::string who = "at full pull (" + shown(fastest) + " m/s) the " + first->name + " bird";
    const std::string allowed =
        "the claim allows " + shown(reach.withinDeg) + "° either side of the best angle, " + shown(best) + "°";
    const std::string what = "first strikes a pig at x " + rangeText(reach.pigX);
    if (!lowest)
        result.message = who + " never " + what + " at any angle from 0 to 90° (" + allowed + ")";
    else
        result.message = who + " " + what + " at angles from " + shown(angleOf(*lowest)) + " to " +
                         shown(angleOf(*highest)) + "°" +
                         (outside > 0 ? ", " + std::to_string(outside) + " of them farther from the best" : "") +
                         (bestReaches ? "" : ", not at the best angle") + " (" + allowed + ")";
    return result;
}

/// One play of a cannot-break claim: a bird, an aim, its ability at a share of the time to the first contact
/// (kCannotBreakAbilityShares) or not at all (0).
struct BreakTrial
{
    std::string bird;
    double angleDeg = 0.0;
    double speedMps = 0.0;
    double abilityShare = 0.0;
};

/// What one play of a cannot-break claim shows: the first block of the material that breaks (and counts for the
/// claim), or -1, and when the bird first touched something.
struct BreakPlay
{
    int broken = -1;
    std::optional<double> contactS;
};

BreakPlay playForBreak(const CannotBreakClaimDef& claim, const LevelDef& level, const Catalog& catalog,
                       const BreakTrial& trial, std::optional<double> abilityAt)
{
    LevelDef played = level;
    // A second bird keeps the level going after the shot, so that a tower still falling is watched to the end.
    played.birds = {trial.bird, trial.bird};
    const std::unique_ptr<GameSession> session =
        simulateShots(played, {{trial.angleDeg, trial.speedMps, abilityAt}}, catalog);
    BreakPlay play;
    if (const auto& contact = session->shots().at(0).actualContact)
        play.contactS = contact->t;
    while (!session->finished() && session->timeSinceLaunch() < kOutcomeWatchS)
        session->step();
    for (const DestroyedEvent& event : session->defeats())
        if (event.kind == EntityKind::Block && event.index >= 0 &&
            level.blocks[static_cast<std::size_t>(event.index)].material == claim.material &&
            (!claim.byBirdOnly || event.cause.kind == CauseKind::Bird))
        {
            play.broken = event.index;
            break;
        }
    return play;
}

ClaimResult evaluateCannotBreak(const CannotBreakClaimDef& claim, const LevelDef& level, const Catalog& catalog)
{
    ClaimResult result;
    const Catalog own = levelCatalog(level, catalog);
    // Every bird the level offers, over a grid of first shots and the fan around each, the ability used halfway to the
    // first contact, just before it and at it (the black bird's blast on what it struck), and not at all (the black
    // bird then goes off by itself).
    std::vector<BreakTrial> trials;
    std::vector<std::string> birds;
    for (const std::string& name : level.birds)
        if (std::find(birds.begin(), birds.end(), name) == birds.end())
            birds.push_back(name);
    for (const std::string& name : birds)
    {
        const BirdType* bird = own.findBird(name);
        if (bird == nullptr)
            continue;
        const double fastest = maxLaunchSpeed(level, *bird, own);
        for (const double angle : kCannotBreakAnglesDeg)
            for (const double share : kCannotBreakPulls)
                for (const double da : {-kOutcomeFanAngleStepDeg, 0.0, kOutcomeFanAngleStepDeg})
                    for (const double dv : {-kOutcomeFanSpeedStepMps, 0.0, kOutcomeFanSpeedStepMps})
                    {
                        const double speed = std::clamp(share * fastest + dv, 0.0, fastest);
                        trials.push_back({name, angle + da, speed, 0.0});
                        if (bird->ability)
                            for (const double abilityShare : kCannotBreakAbilityShares)
                                trials.push_back({name, angle + da, speed, abilityShare});
                    }
    }
    // Each aim is played once without its ability; that play's first contact times the ability's trials, which
    // follow it in the list.
    std::vector<std::size_t> plainTrials;
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (trials[i].abilityShare <= 0.0)
            plainTrials.push_back(i);
    std::vector<int> broken(trials.size(), -1);
    try
    {
        parallelFor(
            plainTrials.size(), workerCount(0),
            [&](std::size_t k)
            {
                const std::size_t i = plainTrials[k];
                const BreakPlay plain = playForBreak(claim, level, catalog, trials[i], std::nullopt);
                broken[i] = plain.broken;
                // A bird that touched nothing has no contact to time its ability by: the plain play covers it.
                for (std::size_t j = i + 1; plain.contactS && j < trials.size() && trials[j].abilityShare > 0.0; ++j)
                    broken[j] =
                        playForBreak(claim, level, catalog, trials[j], trials[j].abilityShare * *plain.contactS).broken;
            },
            [](std::size_t) {});
    }
    catch (const LaunchError& e)
    {
        result.message = std::string("cannot be computed: ") + e.what();
        return result;
    }
    const auto first = std::find_if(broken.begin(), broken.end(), [](int index) { return index >= 0; });
    result.holds = first == broken.end();
    result.left = static_cast<double>(std::count_if(broken.begin(), broken.end(), [](int i) { return i >= 0; }));
    result.right = static_cast<double>(trials.size());
    std::string birdList;
    for (const std::string& name : birds)
        birdList += (birdList.empty() ? "" : ", ") + name;
    const std::string happens = claim.byBirdOnly ? "is broken by a bird's hit" : "breaks";
    if (result.holds)
        result.message = "no " + claim.material + " block " + happens + " in " + std::to_string(trials.size()) +
                         " shots (" + birdList +
                         "; a grid of aims and the fan around each; abilities halfway to contact, just before, at "
                         "contact and unused)";
    else
    {
        const BreakTrial& t = trials[static_cast<std::size_t>(first - broken.begin())];
        result.message =
            "a " + claim.material + " block " + happens + " in " + shown(result.left) + " of " +
            std::to_string(trials.size()) + " shots, first block " + std::to_string(*first) + " by the " + t.bird +
            " bird at " + shown(t.angleDeg) + "\u00B0, " + shown(t.speedMps) + " m/s" +
            (t.abilityShare >= 1.0  ? ", its ability at contact"
             : t.abilityShare > 0.0 ? ", its ability at " + shown(100.0 * t.abilityShare) + " % of the time to contact"
                                    : ", no ability");
    }
    return result;
}

} // namespace

std::optional<ClaimParts> splitClaim(std::string_view holds, std::string& error)
{
    std::optional<std::size_t> at;
    std::size_t length = 0;
    for (std::size_t i = 0; i < holds.size(); ++i)
    {
        if (holds[i] != '<' && holds[i] != '>')
            continue;
        if (at)
        {
            error = "expected one comparison (< > <= >=), found a second at character " + std::to_string(i + 1);
            return std::nullopt;
        }
        at = i;
        length = i + 1 < holds.size() && holds[i + 1] == '=' ? 2 : 1;
        i += length - 1;
    }
    if (!at)
    {
        error = "expected EXPRESSION < EXPRESSION (or >, <=, >=), found no comparison";
        return std::nullopt;
    }
    ClaimParts parts;
    parts.left = trimmed(holds.substr(0, *at));
    parts.op = holds.substr(*at, length);
    parts.rightOffset = *at + length;
    parts.right = trimmed(holds.substr(parts.rightOffset));
    while (parts.rightOffset < holds.size() && holds[parts.rightOffset] == ' ')
        ++parts.rightOffset;
    if (parts.left.empty() || parts.right.empty())
    {
        error = std::string("expected an expression on each side of ") + std::string(parts.op);
        return std::nullopt;
    }
    return parts;
}

std::vector<std::pair<std::size_t, std::string>> checkClaim(std::string_view holds, const LevelDef& level,
                                                            const Catalog& catalog)
{
    std::string error;
    const std::optional<ClaimParts> parts = splitClaim(holds, error);
    if (!parts)
        return {{0, error}};
    std::vector<std::pair<std::size_t, std::string>> problems;
    const std::size_t leftOffset = static_cast<std::size_t>(parts->left.data() - holds.data());
    if (const auto e = checkExpression(parts->left, level, catalog))
        problems.emplace_back(leftOffset + e->offset(), e->what());
    if (const auto e = checkExpression(parts->right, level, catalog))
        problems.emplace_back(parts->rightOffset + e->offset(), e->what());
    return problems;
}

ClaimResult evaluateClaim(const ClaimDef& claim, const LevelDef& level, const Catalog& catalog)
{
    if (claim.outcome)
        return evaluateOutcome(*claim.outcome, level, catalog);
    if (claim.cannotBreak)
        return evaluateCannotBreak(*claim.cannotBreak, level, catalog);
    if (claim.reach)
        return evaluateReach(*claim.reach, level, catalog);
    ClaimResult result;
    std::string error;
    const std::optional<ClaimParts> parts = splitClaim(claim.holds, error);
    if (!parts)
    {
        result.message = error;
        return result;
    }
    try
    {
        result.left = evaluateExpression(parts->left, level, catalog);
        result.right = evaluateExpression(parts->right, level, catalog);
    }
    catch (const TextValueError& e)
    {
        result.message = std::string("cannot be computed: ") + e.what();
        return result;
    }
    const std::string_view op = parts->op;
    result.holds = op == "<"    ? result.left < result.right
                   : op == ">"  ? result.left > result.right
                   : op == "<=" ? result.left <= result.right
                                : result.left >= result.right;
    // "best_angle:red = 34.01", or just "45" for a number written as such.
    const auto side = [](std::string_view written, double value)
    {
        const std::string text(written);
        char* end = nullptr;
        std::strtod(text.c_str(), &end);
        return end != nullptr && *end == '\0' ? text : text + " = " + shown(value);
    };
    result.message = side(parts->left, result.left) + (result.holds ? " is " : " is not ") + std::string(op) + " " +
                     side(parts->right, result.right);
    return result;
}

} // namespace abalike

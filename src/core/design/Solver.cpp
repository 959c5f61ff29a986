#include "design/DropAims.hpp"
#include "design/ParallelFor.hpp"

#include <abalike/design/AimRange.hpp>
#include <abalike/design/Solver.hpp>
#include <abalike/game/SessionBranch.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/util/Bytes.hpp>
#include <abalike/world/RestCheck.hpp>

#include <chrono>
#include <cmath>
#include <memory>
#include <set>
#include <tuple>

namespace abalike
{

namespace
{

/// The coarse grid aims between these angles: flatter shots hit the ground, steeper ones rarely help.
/// Ability times tried, as fractions of the time to the bird's first contact without it.
constexpr double kAbilityFractions[] = {0.3, 0.5, 0.7, 0.9};
/// Best candidates of a bird that are refined and tried with abilities.
constexpr std::size_t kRefineCount = 3;
/// Shots tried per standing pig and prefix with a payload dropped on it: those whose payload would fall fastest (3
/// missed 4-8's cellar once the white bird flew faster).
constexpr std::size_t kDropTries = 4;
/// Offsets, in seconds, tried around each estimated drop moment: the estimate ignores drag and what the payload
/// strikes on its way down (a hatch's edge, a rim), and a bird flying 8 m/s sideways moves 0.4 m in 0.05 s.
constexpr double kDropSpreadS[] = {0.0, -0.05, 0.05};

/// Shots written with few digits survive any round trip through text (JSON, --shot A,S) bit for bit: dividing by
/// a whole number of steps per unit gives the double nearest to the decimal, which prints as that decimal.
double roundTo(double value, double stepsPerUnit)
{
    return std::round(value * stepsPerUnit) / stepsPerUnit;
}

double floorTo(double value, double stepsPerUnit)
{
    return std::floor(value * stepsPerUnit) / stepsPerUnit;
}

struct Candidate
{
    std::size_t prefix = 0; ///< index into the stage's prefixes
    ScriptedShot shot;
};

struct Evaluated
{
    std::vector<ScriptedShot> shots;
    ShotOutcome outcome;
    std::optional<double> lastContactS; ///< when the last shot first touched something, after its launch
    std::vector<DropAim> drops;         ///< a bird that drops a payload: moments its shot flew over a standing pig
    bool valid = false;
};

/// Better first: won, fewer pigs left, higher score. Ties keep their order (a stable sort by candidate index).
bool better(const Evaluated& a, const Evaluated& b)
{
    if (a.valid != b.valid)
        return a.valid;
    return std::make_tuple(a.outcome.won, -a.outcome.pigsRemaining, a.outcome.score) >
           std::make_tuple(b.outcome.won, -b.outcome.pigsRemaining, b.outcome.score);
}

/// A candidate's bytes start with whether it could be played (a launch it refused is no candidate).
constexpr char kCandidatePlayed = 'p';
constexpr char kCandidateRefused = 'x';

using ShotKey = std::tuple<std::size_t, double, double, double>;

ShotKey keyOf(const Candidate& c)
{
    return {c.prefix, c.shot.angleDeg, c.shot.speedMps, c.shot.abilityAtS.value_or(-1.0)};
}

class Search
{
public:
    Search(const LevelDef& level, const Catalog& catalog, const SolverOptions& options)
        : m_level(level), m_catalog(levelCatalog(level, catalog)), m_options(options),
          m_threads(workerCount(options.threads))
    {
        const std::size_t birds = level.birds.size();
        const std::size_t grid = static_cast<std::size_t>(std::max(1, options.angleSteps)) *
                                 std::max<std::size_t>(1, options.speedFractions.size());
        const std::size_t perPrefix = grid + static_cast<std::size_t>(options.refineRounds) * kRefineCount * 8 +
                                      (options.tryAbilities ? kRefineCount * std::size(kAbilityFractions) : 0);
        m_estimate = perPrefix * (1 + (birds - 1) * static_cast<std::size_t>(std::max(1, options.beamWidth)));
    }

    Solution run()
    {
        const auto start = std::chrono::steady_clock::now();
        std::vector<std::vector<ScriptedShot>> prefixes{{}};
        Evaluated best;
        for (std::size_t bird = 0; bird < m_level.birds.size() && !prefixes.empty(); ++bird)
        {
            std::vector<Evaluated> stage = searchBird(bird, prefixes);
            if (!stage.empty() && better(stage.front(), best))
                best = stage.front();
            if (best.outcome.won)
                break; // a win with fewer birds keeps the unused-bird bonus: later birds cannot beat it
            prefixes.clear();
            for (const Evaluated& e : stage)
            {
                if (prefixes.size() >= static_cast<std::size_t>(std::max(1, m_options.beamWidth)))
                    break;
                if (e.valid && !e.outcome.finished)
                    prefixes.push_back(e.shots);
            }
        }
        report(m_estimate);
        Solution solution;
        solution.shots = best.shots;
        solution.outcome = best.outcome;
        solution.simulations = m_simulations;
        solution.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return solution;
    }

private:
    /// Every candidate shot for one bird after each prefix, ranked best first.
    std::vector<Evaluated> searchBird(std::size_t birdIndex, const std::vector<std::vector<ScriptedShot>>& prefixes)
    {
        m_seen.clear(); // prefix indices name different sequences from one bird to the next
        playPrefixes(prefixes);
        const BirdType* bird = m_catalog.findBird(m_level.birds[birdIndex]);
        m_payload = bird->ability ? bird->ability->dropped() : std::nullopt;
        const double top = floorTo(maxLaunchSpeed(m_level, *bird, m_catalog), 100);
        std::vector<Candidate> candidates;
        for (std::size_t p = 0; p < prefixes.size(); ++p)
            for (int a = 0; a < m_options.angleSteps; ++a)
                for (const double fraction : m_options.speedFractions)
                {
                    const double t = m_options.angleSteps > 1 ? double(a) / (m_options.angleSteps - 1) : 0.5;
                    const double angle = roundTo(kAimMinAngleDeg + t * (kAimMaxAngleDeg - kAimMinAngleDeg), 10);
                    candidates.push_back({p, {angle, floorTo(fraction * top, 100), std::nullopt}});
                }
        std::vector<Evaluated> ranked;
        evaluate(prefixes, candidates, ranked);

        // Refine around the best few: a smaller step each round.
        double angleStep = (kAimMaxAngleDeg - kAimMinAngleDeg) / std::max(1, m_options.angleSteps - 1) / 2;
        double speedStep = 0.05 * top;
        for (int round = 0; round < m_options.refineRounds; ++round)
        {
            std::vector<Candidate> next;
            for (std::size_t i = 0; i < std::min(kRefineCount, ranked.size()); ++i)
            {
                const Candidate base = candidateOf(ranked[i], prefixes);
                for (int da = -1; da <= 1; ++da)
                    for (int ds = -1; ds <= 1; ++ds)
                    {
                        if (da == 0 && ds == 0)
                            continue;
                        Candidate c = base;
                        c.shot.angleDeg = std::clamp(roundTo(base.shot.angleDeg + da * angleStep, 10), -90.0, 90.0);
                        c.shot.speedMps = std::clamp(floorTo(base.shot.speedMps + ds * speedStep, 100), 0.0, top);
                        next.push_back(c);
                    }
            }
            evaluate(prefixes, next, ranked);
            angleStep /= 2;
            speedStep /= 2;
        }

        // The bird's ability at a few moments before its first contact.
        if (m_options.tryAbilities && bird->ability)
        {
            std::vector<Candidate> next;
            for (std::size_t i = 0; i < std::min(kRefineCount, ranked.size()); ++i)
            {
                if (!ranked[i].lastContactS || ranked[i].shots.back().abilityAtS)
                    continue;
                for (const double fraction : kAbilityFractions)
                {
                    Candidate c = candidateOf(ranked[i], prefixes);
                    c.shot.abilityAtS = std::max(0.05, roundTo(fraction * *ranked[i].lastContactS, 100));
                    next.push_back(c);
                }
            }
            evaluate(prefixes, next, ranked);
        }
        // A payload (the egg) dropped over each pig still standing, from the shots that flew over it.
        if (m_options.tryAbilities && m_payload)
            evaluate(prefixes, dropCandidates(ranked, prefixes), ranked);
        m_payload.reset();
        return ranked;
    }

    /// For each prefix and standing pig, the kDropTries shots (without the ability) whose payload would reach the
    /// pig fastest, each with its drop at the moment the estimate gives.
    static std::vector<Candidate> dropCandidates(const std::vector<Evaluated>& ranked,
                                                 const std::vector<std::vector<ScriptedShot>>& prefixes)
    {
        struct Try
        {
            std::size_t prefix;
            int pig;
            double blowMps;
            Candidate candidate;
        };
        std::vector<Try> tries;
        for (const Evaluated& e : ranked)
        {
            if (!e.valid || e.shots.back().abilityAtS)
                continue;
            const Candidate base = candidateOf(e, prefixes);
            for (const DropAim& aim : e.drops)
            {
                Candidate c = base;
                c.shot.abilityAtS = std::max(0.05, roundTo(aim.atS, 100));
                tries.push_back({base.prefix, aim.pig, aim.blowMps, c});
            }
        }
        // Fastest first; equal ones keep the ranking's order.
        std::stable_sort(tries.begin(), tries.end(),
                         [](const Try& a, const Try& b)
                         { return std::tie(a.prefix, a.pig, b.blowMps) < std::tie(b.prefix, b.pig, a.blowMps); });
        std::vector<Candidate> chosen;
        std::size_t taken = 0;
        for (std::size_t i = 0; i < tries.size(); ++i)
        {
            const bool samePig = i > 0 && tries[i - 1].prefix == tries[i].prefix && tries[i - 1].pig == tries[i].pig;
            taken = samePig ? taken + 1 : 0;
            if (taken >= kDropTries)
                continue;
            for (const double offsetS : kDropSpreadS)
            {
                Candidate c = tries[i].candidate;
                c.shot.abilityAtS = std::max(0.05, roundTo(*c.shot.abilityAtS + offsetS, 100));
                chosen.push_back(c);
            }
        }
        return chosen;
    }

    /// The candidate an evaluated sequence came from: its prefix and its last shot.
    static Candidate candidateOf(const Evaluated& e, const std::vector<std::vector<ScriptedShot>>& prefixes)
    {
        const std::vector<ScriptedShot> prefix(e.shots.begin(), e.shots.end() - 1);
        std::size_t p = 0;
        while (p < prefixes.size() && !samePrefix(prefixes[p], prefix))
            ++p;
        return {p, e.shots.back()};
    }

    static bool samePrefix(const std::vector<ScriptedShot>& a, const std::vector<ScriptedShot>& b)
    {
        if (a.size() != b.size())
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].angleDeg != b[i].angleDeg || a[i].speedMps != b[i].speedMps || a[i].abilityAtS != b[i].abilityAtS)
                return false;
        return true;
    }

    /// Plays the candidates not seen before (in parallel) and merges them into ranked, best first.
    void evaluate(const std::vector<std::vector<ScriptedShot>>& prefixes, const std::vector<Candidate>& candidates,
                  std::vector<Evaluated>& ranked)
    {
        std::vector<Candidate> fresh;
        for (const Candidate& c : candidates)
            if (m_seen.insert(keyOf(c)).second)
                fresh.push_back(c);
        std::vector<Evaluated> results(fresh.size());
        const bool wantDrops = m_payload.has_value();
        parallelForBytes(
            fresh.size(), m_threads,
            [&](std::size_t i) -> std::string
            {
                try
                {
                    return kCandidatePlayed +
                           m_branches[fresh[i].prefix]->trial(
                               fresh[i].shot, [&](const GameSession& session)
                               { return trialBytes(session, wantDrops && !fresh[i].shot.abilityAtS); });
                }
                catch (const LaunchError&)
                {
                    return std::string(1, kCandidateRefused);
                }
            },
            [&](std::size_t i, const std::string& bytes)
            {
                Evaluated& e = results[i];
                e.shots = prefixes[fresh[i].prefix];
                e.shots.push_back(fresh[i].shot);
                e.valid = !bytes.empty() && bytes.front() == kCandidatePlayed;
                if (!e.valid)
                    return;
                BytesIn in(std::string_view(bytes).substr(1));
                e.outcome = in.get<ShotOutcome>();
                e.lastContactS = in.get<std::optional<double>>();
                e.drops = in.getVector<DropAim>();
            },
            [&](std::size_t) { report(++m_done); });
        m_simulations += fresh.size();
        ranked.insert(ranked.end(), std::make_move_iterator(results.begin()), std::make_move_iterator(results.end()));
        // Stable: equal sequences keep the order they were generated in, whatever thread finished first.
        std::stable_sort(ranked.begin(), ranked.end(), better);
    }

    /// What a candidate's play leaves for the ranking: its outcome, when its shot first touched something, and
    /// where a payload could be dropped on a standing pig.
    std::string trialBytes(const GameSession& session, bool withDrops) const
    {
        std::optional<double> contactS;
        if (!session.shots().empty() && session.shots().back().actualContact)
            contactS = session.shots().back().actualContact->t;
        BytesOut out;
        out.put(outcomeOf(session)).put(contactS);
        out.putVector(withDrops ? dropAims(session, *m_payload) : std::vector<DropAim>{});
        return out.take();
    }

    /// The games played up to each prefix: played once per bird's search, and every candidate goes on from one.
    void playPrefixes(const std::vector<std::vector<ScriptedShot>>& prefixes)
    {
        m_branches.clear();
        m_branches.resize(prefixes.size());
        parallelFor(
            prefixes.size(), m_threads,
            [&](std::size_t p) { m_branches[p] = std::make_unique<SessionBranch>(m_level, prefixes[p], m_catalog); },
            [](std::size_t) {});
    }

    void report(std::size_t done)
    {
        m_estimate = std::max(m_estimate, done);
        if (m_options.progress)
            m_options.progress(done, m_estimate);
    }

    const LevelDef& m_level;
    Catalog m_catalog; ///< as the level sees it (its custom bird, its materials)
    const SolverOptions& m_options;
    unsigned m_threads = 1;
    std::size_t m_estimate = 0;
    std::size_t m_done = 0;
    std::size_t m_simulations = 0;
    std::set<ShotKey> m_seen;
    std::vector<std::unique_ptr<SessionBranch>> m_branches; ///< one per prefix of the bird being searched
    std::optional<DroppedPayload> m_payload;                ///< what the bird being searched drops, if anything
};

} // namespace

ShotOutcome outcomeOf(const GameSession& session)
{
    ShotOutcome out;
    out.won = session.phase() == Phase::Won;
    // A time-limited level counts as won only if play was over by the limit: the end of play is a conservative
    // stand-in for the moment the last pig fell, whatever the session itself does about the clock.
    if (const auto limit = session.level().timeLimitS; out.won && limit && session.simTime() > *limit)
        out.won = false;
    out.finished = session.finished();
    out.score = session.score().total();
    out.stars = out.won ? session.stars() : 0;
    out.pigsRemaining = session.pigsRemaining();
    out.birdsUsed = session.birdsUsed();
    return out;
}

ShotOutcome playShots(const LevelDef& level, const std::vector<ScriptedShot>& shots, const Catalog& catalog)
{
    return outcomeOf(*simulateShots(level, shots, catalog));
}

Solution solveLevel(const LevelDef& level, const Catalog& catalog, const SolverOptions& options)
{
    if (level.birds.empty())
        return {};
    // A pig that falls before any shot is not the player's to win: do not count it.
    Solution refused;
    for (const BodyRest& body : checkRest(level, catalog).bodies)
        if (body.kind == EntityKind::Pig && (body.destroyed || body.damaged))
            refused.pigsFallingAlone.push_back(body.defIndex);
    if (!refused.pigsFallingAlone.empty())
    {
        refused.outcome.pigsRemaining = static_cast<int>(level.pigs.size());
        for (int i = 0; i < static_cast<int>(level.pigs.size()); ++i)
            refused.survivingPigs.push_back(i);
        return refused;
    }
    Solution solution = Search(level, catalog, options).run();
    if (!solution.outcome.won)
    {
        const auto session = simulateShots(level, solution.shots, catalog);
        for (const Entity& e : session->world().entities())
            if (e.kind == EntityKind::Pig && e.alive)
                solution.survivingPigs.push_back(e.defIndex);
    }
    return solution;
}

} // namespace abalike

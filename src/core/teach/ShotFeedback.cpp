#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/ImpactAccount.hpp>
#include <abalike/teach/RangeChart.hpp>
#include <abalike/teach/ShotFeedback.hpp>
#include <cmath>
#include <cstdio>
#include <string>

namespace abalike
{

namespace
{

/// The most sentences one shot gets: more would not be read between shots.
constexpr std::size_t kMaxSentences = 2;
/// Below these the wind or the drag did not change the shot enough to be worth a sentence.
constexpr double kWindShiftWorthM = 0.2;
constexpr double kDragShareWorth = 0.01;

std::string format(const char* pattern, auto... values)
{
    char text[320];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

/// The impact sentence's gist, short enough for one line.
std::string momentumBrief(const ImpactAccount& account)
{
    if (!account.broke)
        return format("The bird and %s pushed each other with %.0f N\u00B7s.", account.bodyName.c_str(),
                      std::hypot(account.exchanged.x, account.exchanged.y));
    return format("The bird %s %s %s.", account.bodyIsPig ? "defeated" : "broke", account.bodyName.c_str(),
                  account.birdKeptDirection ? "and flew on" : "but was turned back");
}

/// A sentence of feedback and its gist.
struct Said
{
    std::string full;
    std::string brief;
};

std::vector<Said> compose(const LevelDef& level, const Catalog& catalog, const ShotRecord& shot, double physicsDtS)
{
    std::vector<Said> sentences;
    const BirdType* bird = catalog.findBird(shot.bird);
    if (bird == nullptr)
        return sentences;
    RangeLaunch launch;
    launch.model = levelFlightModel(level.environment, *bird);
    launch.settings.dtS = physicsDtS;
    launch.speedMps = shot.speedMps;
    launch.heightM = std::max(0.0, level.slingshot.y - level.groundY);
    launch.maxTimeS = 30.0;
    const unsigned terms = activeTerms(launch.model);
    const bool drag = (terms & (kLinearDragTerm | kQuadraticDragTerm)) != 0;
    const bool wind = (terms & (kWindTerm | kGustTerm)) != 0;
    const std::optional<double> range = rangeAtAngle(launch, shot.angleDeg);

    if (shot.impact)
    {
        const ImpactAccount account = accountImpact(*shot.impact, catalog);
        sentences.push_back({impactSentence(account), momentumBrief(account)});
    }
    if (wind && range)
    {
        RangeLaunch calm = launch;
        calm.model.windX = calm.model.windY = 0.0;
        calm.model.gusts.reset();
        if (const std::optional<double> still = rangeAtAngle(calm, shot.angleDeg);
            still && std::abs(*range - *still) >= kWindShiftWorthM)
            sentences.push_back(
                {format("The wind moved the landing point %.1f m %s: %.1f m instead of %.1f m in "
                        "still air.",
                        std::abs(*range - *still), *range > *still ? "forward" : "back", *range, *still),
                 format("The wind moved the landing point %.1f m %s.", std::abs(*range - *still),
                        *range > *still ? "forward" : "back")});
    }
    if (drag)
    {
        RangeLaunch vacuum = launch;
        vacuum.model.linearDrag = vacuum.model.quadraticDrag = 0.0;
        const std::optional<double> airless = rangeAtAngle(vacuum, shot.angleDeg);
        // The launch energy the energy panel shows beside it: kinetic + potential, one number on the screen.
        const double launchJ = shot.energy ? shot.energy->launchKineticJ + shot.energy->launchPotentialJ : 0.0;
        // Two landing points that print alike are not worth comparing ("1.7 m away instead of 1.7 m").
        const bool landsElsewhere = airless && range && std::abs(*airless - *range) >= 0.05;
        if (shot.energy && launchJ > 0.0 && std::abs(shot.energy->dragLossJ) >= kDragShareWorth * launchJ)
        {
            const double loss = shot.energy->dragLossJ;
            std::string text = loss >= 0.0 ? format("Air drag took %.0f J of the %.0f J the bird launched with "
                                                    "(kinetic + potential, %.0f %%) before the first contact",
                                                    loss, launchJ, 100.0 * loss / launchJ)
                                           : format("The wind pushed %.0f J into the flight on top of the %.0f J "
                                                    "the bird launched with (kinetic + potential), before the first "
                                                    "contact",
                                                    -loss, launchJ);
            if (landsElsewhere)
                text += format("; in vacuum its centre would come down to the ground %.1f m away, in this air %.1f m",
                               *airless, *range);
            sentences.push_back({text + ".", loss >= 0.0 ? format("Air drag took %.0f %% of the bird's launch energy.",
                                                                  100.0 * loss / launchJ)
                                                         : format("The wind pushed %.0f J into the flight.", -loss)});
        }
        else if (landsElsewhere && std::abs(*airless - *range) >= kWindShiftWorthM)
            sentences.push_back(
                {format("In vacuum this launch would land %.1f m away instead of %.1f m.", *airless, *range),
                 format("In vacuum it would land %.1f m away, not %.1f m.", *airless, *range)});
    }
    else if (range)
    {
        // No air: the path is a parabola, and the lesson is the angle. Every distance is to where the bird's centre
        // comes down to a height (the convention of predict, the chart and the predict lesson's card), and the
        // sentence says which: from a raised slingshot the range to the ground is not v^2 sin 2a / g and the best
        // angle is not 45 degrees, which is what the lessons teach for a launch from the ground.
        RangeLaunch level = launch;
        level.heightM = 0.0;
        // Back at the launch height: only a launch upwards from above the ground comes back there.
        double backM = 0.0;
        bool comesBack = false;
        if (shot.angleDeg > 0.0 && launch.heightM > 0.0)
            if (const std::optional<double> back = rangeAtAngle(level, shot.angleDeg))
            {
                backM = *back;
                comesBack = true;
            }
        std::string text = format("With no air (g = %.2f m/s\u00B2), %.1f\u00B0 at %.1f m/s ", launch.model.gravity,
                                  shot.angleDeg, shot.speedMps);
        if (comesBack)
            text += format("brings the bird's centre back to the launch height %.1f m away and down to the ground, "
                           "%.1f m lower, %.1f m away",
                           backM, launch.heightM, *range);
        else
            text += format("brings the bird's centre down to the ground %.1f m away", *range);
        const std::string brief =
            comesBack ? format("No air: back at the launch height at %.1f m, at the ground at %.1f m.", backM, *range)
                      : format("With no air it came down to the ground %.1f m away.", *range);
        const RangeChart chart = rangeChart(launch, 0.0, 90.0, 1.0);
        if (chart.bestAngleDeg && chart.bestRangeM)
            text += launch.heightM > 0.0
                        ? format("; from that height %.1f\u00B0 reaches the furthest, %.1f m (from the "
                                 "ground: 45\u00B0, v\u00B2/g = %.1f m)",
                                 *chart.bestAngleDeg, *chart.bestRangeM,
                                 shot.speedMps * shot.speedMps / launch.model.gravity)
                        : format("; %.1f\u00B0 reaches the furthest, %.1f m", *chart.bestAngleDeg, *chart.bestRangeM);
        sentences.push_back({text + ".", brief});
    }
    if (sentences.size() > kMaxSentences)
        sentences.resize(kMaxSentences);
    return sentences;
}

} // namespace

std::vector<std::string> shotFeedback(const LevelDef& level, const Catalog& catalog, const ShotRecord& shot,
                                      double physicsDtS)
{
    std::vector<std::string> out;
    for (Said& said : compose(level, catalog, shot, physicsDtS))
        out.push_back(std::move(said.full));
    return out;
}

std::string shotSummary(const LevelDef& level, const Catalog& catalog, const ShotRecord& shot, double physicsDtS)
{
    std::vector<Said> said = compose(level, catalog, shot, physicsDtS);
    return said.empty() ? std::string() : std::move(said.front().brief);
}

} // namespace abalike

#include "bench/BenchSuite.hpp"
#include "bench/PerfParts.hpp"
#include "bench/ReportTable.hpp"
#include "bench/StabilityFlight.hpp"
#include "bench/StabilityWorld.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

namespace abalike::app
{

namespace
{

/// What plain RK4 did, in words.
std::string plainOutcome(const StabilityResult& r)
{
    if (!r.plainFinite)
        return "diverged (non-finite at " + formatSignificant(r.plainBlowUpS, 3) + " s)";
    if (!(r.plainError <= kStabilityTolerance))
        return "wrong (error " + formatSignificant(r.plainError, 2) + ")";
    return "fine (" + formatSignificant(r.plainError, 2) + ")";
}

std::string guardOutcome(const StabilityResult& r)
{
    std::string text = r.guard;
    if (r.guard != "none")
        text += ", " + std::to_string(r.substeps) + " extra steps";
    return text;
}

} // namespace

int runStabilityBench(const BenchOptions& options)
{
    const auto started = std::chrono::steady_clock::now();
    ReportTable flights({"group", "case", "|lambda| dt at launch", "plain RK4 (relative error)", "guarded preview does",
                         "guarded error", "time (ms)", "passed"});
    int passed = 0;
    int failed = 0;
    int plainBroken = 0;
    std::string failures;
    for (const StabilityCase& c : stabilityCases(options.quick))
    {
        const StabilityResult r = runStabilityCase(c, options.quick);
        flights.addRow({c.group, c.name, formatSignificant(r.launchLambdaDt, 3), plainOutcome(r), guardOutcome(r),
                        formatSignificant(r.guardedError, 2), formatSignificant(r.guardedUs / 1e3, 3),
                        r.passed ? "yes" : "NO"});
        (r.passed ? passed : failed) += 1;
        plainBroken += (!r.plainFinite || !(r.plainError <= kStabilityTolerance)) ? 1 : 0;
        if (!r.passed)
            failures += "  " + c.group + ": " + c.name + "\n";
    }
    std::cout << "Extreme and stiff flights, 60 s each, preview settings (RK4, 1/60 s, guard on) against dopri5 at "
                 "1e-12:\n"
              << flights.text() << "\n";

    ReportTable world({"group", "launches", "runs", "NaN", "deepest penetration (m)", "tunnelled", "contacts compared",
                       "worst predicted vs actual (m)", "walls broken", "passed"});
    int worldFailed = 0;
    for (const WorldStabilityRow& row : runWorldStability(options.quick))
    {
        world.addRow({row.group, row.launches, std::to_string(row.runs), row.anyNonFinite ? "YES" : "no",
                      formatSignificant(row.worstPenetrationM, 2), row.tunnelled ? "YES" : "no",
                      std::to_string(row.contactsCompared), formatSignificant(row.worstDeviationM, 2),
                      std::to_string(row.wallsBroken), row.passed ? "yes" : "NO"});
        worldFailed += row.passed ? 0 : 1;
        if (!row.passed)
            failures += "  world: " + row.group + ": " + row.launches + "\n";
    }
    std::cout << "The same extremes in the Box2D world (bird driven by the preview's integrator until first "
                 "contact):\n"
              << world.text() << "\n";

    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::ostringstream md;
    md << "# Stiff and extreme flights\n\n"
       << "Machine: " << machineDescription() << ". Run time " << formatSignificant(elapsed, 3) << " s"
       << (options.quick ? " (--quick: fewer cases)" : "") << ".\n\n"
       << "Each flight lasts 60 s. \"Plain RK4\" is runge_kutta4 at 1/60 s without the guard (`--no-guard`); "
          "\"guarded\" is what the preview and the world actually run: RK4 at 1/60 s whose stiffness guard "
          "re-estimates |lambda| h before every sub-step, sub-steps to keep it <= 0.5, and hands the rest of a step "
          "to rosenbrock4 after 64 sub-steps (and the next steps while they would need more). Errors are the largest "
          "position error along the path divided "
          "by the largest distance flown, against dopri5 at tolerance 1e-12; a case passes when the guarded error "
          "is finite and <= 1e-3.\n\n"
       << passed << " of " << passed + failed << " cases passed; plain RK4 diverged or missed 1e-3 in " << plainBroken
       << " of them.\n\n"
       << flights.markdown() << "\n"
       << "## In the Box2D world\n\n"
       << "A level built in code: flat ground and a 0.2 m wide, 4 m high wall 20 m from the slingshot, either "
          "static terrain or a dynamic stone block (which a fast bird may break: that is a fair way through). "
          "Every bird of the catalog is launched straight at it at speeds up to the world's limit ("
          "GameWorld::maxSpeedMps: 90 % of b2_maxTranslation per sub-step, 8 sub-steps, so about 864 m/s at 60 Hz; "
          "GameSession::maxLaunchSpeed caps the slingshot there). Each launch is watched for a second after its "
          "first contact. Passed: no non-finite value in any body, the bird never crossed the standing wall or the "
          "ground, its leading edge never got more than 3 cm into the wall (Box2D's skin and slop), and predicted "
          "and actual first contact agree within 2 cm. (Below 108 m/s they agree to micrometres. Faster, the world "
          "splits each step into Box2D sub-steps, and Box2D begins a contact as soon as the skins overlap at the "
          "start of a sub-step, up to 3 b2_linearSlop = 1.5 cm before the time-of-impact point the preview's one "
          "cast per step finds.)\n\n"
       << world.markdown();

    bool ok = writeReportFile(options.outDir, "stability.md", md.str());
    std::ostringstream csv;
    csv << flights.csv() << "\n" << world.csv();
    ok &= writeReportFile(options.outDir, "stability.csv", csv.str());
    std::cout << passed << " of " << passed + failed << " flight cases passed, " << worldFailed
              << " world groups failed; wrote stability.md and stability.csv to " << options.outDir << " in "
              << formatSignificant(elapsed, 3) << " s\n";
    if (!failures.empty())
        std::cout << "failed:\n" << failures;
    return ok && failed == 0 && worldFailed == 0 ? 0 : 1;
}

} // namespace abalike::app

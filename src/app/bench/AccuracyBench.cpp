#include "bench/AccuracySweep.hpp"
#include "bench/BenchSuite.hpp"
#include "bench/PerfParts.hpp"
#include "bench/ReportTable.hpp"
#include "bench/RhsCost.hpp"
#include "plot/PlotError.hpp"
#include "plot/PlotPng.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace abalike::app
{

namespace
{

const StepperKind kMethods[] = {StepperKind::Euler, StepperKind::SemiImplicitEuler, StepperKind::Rk4,
                                StepperKind::Dopri5, StepperKind::Analytic};

std::string stepLabel(const SweepPoint& p)
{
    std::ostringstream out;
    out << "1/" << std::lround(1.0 / p.dtS);
    return out.str();
}

ReportTable sweepTable(const ProblemSweep& sweep)
{
    ReportTable table(
        {"method", "dt (s)", "tol", "steps", "RHS evals", "time (us)", "error at end (m)", "max error (m)"});
    for (const SweepPoint& p : sweep.points)
        table.addRow({std::string(stepperName(p.stepper)), stepLabel(p),
                      p.tolerance > 0.0 ? formatSignificant(p.tolerance, 1) : "", std::to_string(p.steps),
                      std::to_string(p.rhsEvaluations), formatSignificant(1e6 * p.seconds, 3),
                      formatSignificant(p.finalError, 2), formatSignificant(p.maxError, 2)});
    return table;
}

std::string orderText(double order)
{
    return std::isnan(order) ? "exact (error at rounding level)" : formatSignificant(order, 3);
}

Plot plotOf(const ProblemSweep& sweep)
{
    Plot plot;
    plot.title = "Flight integration: error against run time";
    plot.subtitle = sweep.problem.label + ", " + formatSignificant(sweep.problem.durationS, 2) +
                    " s flight, median of repeated runs";
    plot.x.label = "wall time per integration (µs)";
    plot.x.scale = AxisScale::Log10;
    plot.y.label = "max position error along the path (m)";
    plot.y.scale = AxisScale::Log10;
    const Marker markers[] = {Marker::Square, Marker::Diamond, Marker::Disc, Marker::Disc, Marker::Square};
    std::size_t index = 0;
    for (const StepperKind method : kMethods)
    {
        PlotSeries series;
        series.label = std::string(stepperName(method)) + (method == StepperKind::Dopri5 ? " (by tol)" : " (by dt)");
        series.colour = plotColour(index);
        series.marker = markers[index];
        series.dashed = method == StepperKind::Dopri5;
        for (const SweepPoint& p : sweep.points)
            if (p.stepper == method && p.maxError > 0.0)
                series.points.emplace_back(1e6 * p.seconds, p.maxError);
        ++index;
        if (!series.points.empty())
            plot.series.push_back(std::move(series));
    }
    for (const SweepPoint& p : sweep.points)
        if (p.stepper == StepperKind::Rk4 && std::lround(1.0 / p.dtS) == 60)
            plot.callouts.push_back({1e6 * p.seconds, p.maxError, "the preview: RK4 at 60 Hz"});
    return plot;
}

/// Where the preview sits on the accuracy curve: RK4 at 1/60 s.
const SweepPoint* previewPoint(const ProblemSweep& sweep)
{
    for (const SweepPoint& p : sweep.points)
        if (p.stepper == StepperKind::Rk4 && std::lround(1.0 / p.dtS) == 60)
            return &p;
    return nullptr;
}

} // namespace

int runAccuracyBench(const BenchOptions& options)
{
    const auto started = std::chrono::steady_clock::now();
    std::ostringstream md;
    md << "# Flight integration accuracy against run time\n\n"
       << "Machine: " << machineDescription() << ". Times are medians of " << (options.quick ? 5 : 21)
       << " timed samples of at least 2 ms each (std::chrono::steady_clock), of one whole integration including "
          "building the integrator"
       << (options.quick ? " (--quick: fewer samples and dt values)" : "") << ". At the start: " << loadAverageNote()
       << " (other processes slow the timings down; compare methods within one run).\n\n"
       << "Errors are position errors against the closed form (vacuum, linear drag) or against dopri5 at tolerance "
          "1e-13 sampled every 1/3840 s; the reference's own error is estimated against a run at 1e-12.\n\n";

    std::ostringstream csv;
    csv << "problem,method,dt_s,tol,steps,rhs_evaluations,time_us,error_end_m,max_error_m\n";
    ReportTable orders({"problem", "euler", "semi-implicit-euler", "rk4", "reference error (m)"});
    bool ok = true;
    for (const AccuracyProblem& problem : accuracyProblems())
    {
        const ProblemSweep sweep = sweepProblem(problem, options.quick);
        const ReportTable table = sweepTable(sweep);
        std::cout << "== " << problem.label << " (" << problem.durationS << " s)\n" << table.text();

        const double euler = convergenceOrder(sweep, StepperKind::Euler);
        const double semi = convergenceOrder(sweep, StepperKind::SemiImplicitEuler);
        const double rk4 = convergenceOrder(sweep, StepperKind::Rk4);
        std::cout << "measured order of convergence: euler " << orderText(euler) << ", semi-implicit-euler "
                  << orderText(semi) << ", rk4 " << orderText(rk4) << "\n";
        const std::string referenceNote =
            sweep.exactReference
                ? "closed form (dopri5 at 1e-13 is " + formatSignificant(sweep.dopriVsExact, 2) + " m from it)"
                : formatSignificant(sweep.referenceError, 2) + " (1e-13 vs 1e-12)";
        std::cout << "reference: " << referenceNote << "\n\n";
        orders.addRow({problem.name, orderText(euler), orderText(semi), orderText(rk4), referenceNote});

        md << "## " << problem.label << "\n\n"
           << "Launch 30 m/s at 50 degrees from 1.5 m, " << problem.durationS
           << " s of flight. Reference: " << referenceNote << ".\n\n";
        if (const SweepPoint* p = previewPoint(sweep))
            md << "The preview's setting, RK4 at 1/60 s, is " << formatSignificant(p->maxError, 2)
               << " m off at worst along the path and takes " << formatSignificant(1e6 * p->seconds, 3)
               << " us for the whole flight (" << p->rhsEvaluations << " right-hand-side evaluations).\n\n";
        md << table.markdown() << "\n";

        for (const SweepPoint& p : sweep.points)
            csv << problem.name << ',' << stepperName(p.stepper) << ',' << p.dtS << ',' << p.tolerance << ',' << p.steps
                << ',' << p.rhsEvaluations << ',' << 1e6 * p.seconds << ',' << p.finalError << ',' << p.maxError
                << '\n';

        const std::string png =
            problem.name == "wind-quadratic-drag" ? "accuracy.png" : "accuracy-" + problem.name + ".png";
        try
        {
            savePlotPng(plotOf(sweep), (std::filesystem::path(options.outDir) / png).string());
        }
        catch (const PlotError& e)
        {
            std::cerr << "abalike: " << e.what() << '\n';
            ok = false;
        }
    }
    std::cout << "Measured orders of convergence (error at the end against dt):\n" << orders.text() << "\n";

    const std::vector<RhsCost> costs = measureRhsCost(options.quick);
    ReportTable costTable({"scene", "terms", "FlightRhs (ns/eval)", "branching RHS (ns/eval)", "preview (us)", "steps",
                           "preview in a level (us)"});
    for (const RhsCost& c : costs)
        costTable.addRow({c.scene, c.terms, formatSignificant(c.composedNs, 3), formatSignificant(c.branchingNs, 3),
                          formatSignificant(c.previewUs, 3), std::to_string(c.previewSteps),
                          formatSignificant(c.sessionPreviewUs, 3)});
    std::cout << "A scene evaluates only the terms it has:\n" << costTable.text();

    md << "## Measured orders of convergence\n\nSlope of log(error at the end) against log(dt), over the dt values "
          "whose error is more than 1000 times the reference's.\n\n"
       << orders.markdown() << "\n"
       << "## What the right-hand side and the preview cost\n\n"
       << "FlightRhs<terms> is compiled for the terms a scene has; the branching right-hand side computes the same "
          "forces but tests for every term on every call. The preview is RK4 at 1/60 s from launch (30 m/s, 50 "
          "degrees) to landing; \"in a level\" is GameSession::preview, which adds a Box2D time-of-impact query per "
          "step against a level with ground and a wall. Medians of repeated batches.\n\n"
       << costTable.markdown() << "\n";

    ok &= writeReportFile(options.outDir, "accuracy.md", md.str());
    ok &= writeReportFile(options.outDir, "accuracy.csv", csv.str());
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::cout << "wrote accuracy.md, accuracy.csv and accuracy*.png to " << options.outDir << " in "
              << formatSignificant(elapsed, 3) << " s\n";
    return ok ? 0 : 1;
}

} // namespace abalike::app

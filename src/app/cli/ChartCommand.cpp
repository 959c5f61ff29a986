#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/Print.hpp"
#include "cli/UsageError.hpp"
#include "plot/PlotError.hpp"
#include "plot/PlotPng.hpp"
#include "plot/TablePng.hpp"

#include <abalike/teach/RangeChart.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike::app
{

namespace
{

/// Most integration steps a chart may need if no angle lands before --max-t: about 10 s on the development machine.
constexpr double kMaxChartSteps = 1e8;

struct RangeArgs
{
    std::string speed, y0 = "0", from = "-90", to = "90", step = "1", maxT = "60", dt;
    FlightModelArgs model;
    std::string out;
    bool json = false;
};

RangeLaunch parseLaunch(const RangeArgs& a)
{
    RangeLaunch launch;
    launch.model = parseFlightModel(a.model);
    launch.speedMps = parseFinite(a.speed, "--speed");
    if (launch.speedMps < 0.0)
        throw UsageError("--speed: must be >= 0 m/s, got " + a.speed);
    launch.heightM = parseFinite(a.y0, "--y0");
    if (launch.heightM < 0.0)
        throw UsageError("--y0: the launch must be at or above the ground (y = 0), got " + a.y0);
    launch.maxTimeS = parseFinite(a.maxT, "--max-t");
    if (launch.maxTimeS <= 0.0)
        throw UsageError("--max-t: must be > 0 s, got " + a.maxT);
    launch.settings.dtS = a.dt.empty() ? 1.0 / 60.0 : parseFinite(a.dt, "--dt");
    if (launch.settings.dtS <= 0.0)
        throw UsageError("--dt: must be > 0 s, got " + a.dt);
    // The same bound on work as predict: every angle may integrate up to --max-t.
    if (launch.maxTimeS / launch.settings.dtS > 2.0e6)
        throw UsageError("--dt " + a.dt + " over --max-t " + a.maxT +
                         " s is more than 2 million steps per angle; use a larger --dt or a shorter --max-t");
    return launch;
}

void printTable(const RangeChart& chart, const RangeLaunch& launch)
{
    print("Range on flat ground (y = 0) at %g m/s from %g m up, by launch angle:\n\n", launch.speedMps, launch.heightM);
    print("%10s  %14s\n", "angle deg", "range m");
    for (std::size_t i = 0; i < chart.anglesDeg.size(); ++i)
    {
        if (chart.rangesM[i])
            print("%10.4g  %14.6f\n", chart.anglesDeg[i], *chart.rangesM[i]);
        else
            print("%10.4g  %14s\n", chart.anglesDeg[i], "no landing");
    }
    if (chart.bestAngleDeg)
        print("\nbest angle %.2f deg: range %.6f m\n", *chart.bestAngleDeg, *chart.bestRangeM);
    else
        print("\nno angle lands within --max-t\n");
}

/// The chart as a PNG: range against angle, the best angle called out with guides to both axes.
void saveRangePng(const RangeChart& chart, const RangeLaunch& launch, const std::string& path)
{
    Plot plot;
    plot.title = "Range by launch angle";
    char text[160];
    std::snprintf(text, sizeof text, "%g m/s from %g m above flat ground, g = %g m/s\u00B2, m = %g kg", launch.speedMps,
                  launch.heightM, launch.model.gravity, launch.model.massKg);
    plot.subtitle = text;
    const unsigned terms = activeTerms(launch.model);
    if ((terms & kQuadraticDragTerm) != 0)
        plot.subtitle += (std::snprintf(text, sizeof text, ", c = %g kg/m", launch.model.quadraticDrag), text);
    if ((terms & kLinearDragTerm) != 0)
        plot.subtitle += (std::snprintf(text, sizeof text, ", b = %g kg/s", launch.model.linearDrag), text);
    if ((terms & kWindTerm) != 0)
        plot.subtitle +=
            (std::snprintf(text, sizeof text, ", wind (%g, %g) m/s", launch.model.windX, launch.model.windY), text);
    if ((terms & kGustTerm) != 0)
        plot.subtitle += ", gusts";
    if ((terms & (kLinearDragTerm | kQuadraticDragTerm)) == 0)
        plot.subtitle += ", no air";
    plot.x.label = "launch angle (\u00B0)";
    plot.x.min = chart.anglesDeg.front();
    plot.x.max = chart.anglesDeg.back();
    plot.y.label = "range (m)";
    PlotSeries series;
    series.label = "range on flat ground (RK4)";
    series.colour = plotColour(0);
    series.marker = chart.anglesDeg.size() > 60 ? Marker::None : Marker::Disc;
    for (std::size_t i = 0; i < chart.anglesDeg.size(); ++i)
        series.points.emplace_back(chart.anglesDeg[i], chart.rangesM[i] ? *chart.rangesM[i] : NAN);
    plot.series.push_back(std::move(series));
    if ((terms & (kLinearDragTerm | kQuadraticDragTerm)) != 0)
    {
        // The same launches without air, for comparison: what drag costs at each angle.
        RangeLaunch vacuum = launch;
        vacuum.model.linearDrag = vacuum.model.quadraticDrag = 0.0;
        PlotSeries airless;
        airless.label = "the same launch in vacuum";
        airless.colour = plotColour(2);
        airless.marker = Marker::None;
        airless.dashed = true;
        for (const double angle : chart.anglesDeg)
            airless.points.emplace_back(angle, rangeAtAngle(vacuum, angle).value_or(NAN));
        plot.series.push_back(std::move(airless));
    }
    if (chart.bestAngleDeg)
    {
        char text[96];
        std::snprintf(text, sizeof text, "best %.2f\u00B0: %.2f m", *chart.bestAngleDeg, *chart.bestRangeM);
        PlotCallout best;
        best.x = *chart.bestAngleDeg;
        best.y = *chart.bestRangeM;
        best.text = text;
        best.style = CalloutStyle::Highlight;
        best.colour = plotColour(1);
        best.guides = true;
        plot.callouts.push_back(best);
    }
    try
    {
        savePlotPng(plot, path);
    }
    catch (const PlotError& e)
    {
        throw UsageError("--out " + path + ": " + e.what());
    }
}

int runRange(const RangeArgs& a)
{
    const RangeLaunch launch = parseLaunch(a);
    const double from = parseFinite(a.from, "--from");
    const double to = parseFinite(a.to, "--to");
    const double step = parseFinite(a.step, "--step");
    if (from < -90.0 || to > 90.0 || from > to)
        throw UsageError("--from/--to: expected -90 <= from <= to <= 90 degrees, got " + a.from + " and " + a.to);
    if (step <= 0.0)
        throw UsageError("--step: must be > 0 degrees, got " + a.step);
    // Bound the worst case (no angle lands before --max-t) so that no input makes the command run for minutes; the
    // golden-section search adds about 20 flights.
    const double angles = std::floor((to - from) / step + 1e-6) + 1.0;
    if (angles > static_cast<double>(kMaxRangeChartAngles))
        throw UsageError("--step: the chart would have more than " + std::to_string(kMaxRangeChartAngles) +
                         " angles; use a larger step");
    if ((angles + 20.0) * (launch.maxTimeS / launch.settings.dtS) > kMaxChartSteps)
        throw UsageError("--from/--to/--step with --max-t and --dt could take more than 100 million steps in all; use "
                         "fewer angles, a shorter --max-t or a larger --dt");
    RangeChart chart;
    try
    {
        chart = rangeChart(launch, from, to, step);
    }
    catch (const std::invalid_argument& e)
    {
        throw UsageError(e.what());
    }
    if (!a.out.empty())
        saveRangePng(chart, launch, a.out);
    if (!a.json)
    {
        printTable(chart, launch);
        return 0;
    }
    using Json = nlohmann::ordered_json;
    Json out;
    out["angles_deg"] = chart.anglesDeg;
    Json ranges = Json::array();
    for (const auto& r : chart.rangesM)
        ranges.push_back(r ? Json(*r) : Json(nullptr));
    out["ranges_m"] = std::move(ranges);
    out["best_angle_deg"] = chart.bestAngleDeg ? Json(*chart.bestAngleDeg) : Json(nullptr);
    out["best_range_m"] = chart.bestRangeM ? Json(*chart.bestRangeM) : Json(nullptr);
    std::cout << out.dump() << '\n';
    return 0;
}

struct TableArgs
{
    std::string csv, out;
    int rows = 20;
    int every = 1;
};

/// `chart table`: a CSV (from `simulate --csv` or the game's export) as a spreadsheet shows it, as a PNG.
int runTable(const TableArgs& a)
{
    if (a.rows < 1 || a.rows > 500)
        throw UsageError("--rows: expected 1 to 500 data rows, got " + std::to_string(a.rows));
    if (a.every < 1)
        throw UsageError("--every: expected 1 or more, got " + std::to_string(a.every));
    std::ifstream in(a.csv);
    if (!in)
        throw UsageError(a.csv + ": cannot read the file");
    const auto split = [](const std::string& line)
    {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream stream(line);
        while (std::getline(stream, cell, ','))
            cells.push_back(cell);
        if (!line.empty() && line.back() == ',')
            cells.emplace_back();
        return cells;
    };
    Table table;
    std::string line;
    std::size_t lineNumber = 0;
    std::size_t dataRows = 0;
    while (std::getline(in, line))
    {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        std::vector<std::string> cells = split(line);
        if (lineNumber == 1)
        {
            if (cells.empty())
                throw UsageError(a.csv + ":1: expected a header row of column names");
            table.cells.push_back(std::move(cells));
            table.rowNumbers.push_back(1);
            continue;
        }
        if (cells.size() != table.cells.front().size())
            throw UsageError(a.csv + ":" + std::to_string(lineNumber) + ": expected " +
                             std::to_string(table.cells.front().size()) + " cells like the header, got " +
                             std::to_string(cells.size()));
        ++dataRows;
        if ((dataRows - 1) % static_cast<std::size_t>(a.every) == 0 &&
            table.cells.size() <= static_cast<std::size_t>(a.rows))
        {
            table.cells.push_back(std::move(cells));
            table.rowNumbers.push_back(lineNumber);
        }
    }
    if (table.cells.empty())
        throw UsageError(a.csv + ": the file is empty");
    table.title = std::filesystem::path(a.csv).filename().string() + ": " + std::to_string(dataRows) + " rows, " +
                  std::to_string(table.cells.size() - 1) + " shown" +
                  (a.every > 1 ? " (every " + std::to_string(a.every) + ")" : "");
    try
    {
        saveTablePng(table, a.out);
    }
    catch (const PlotError& e)
    {
        throw UsageError(std::string("--out: ") + e.what());
    }
    std::cout << "wrote " << a.out << " (" << table.cells.size() - 1 << " of " << dataRows << " rows)\n";
    return 0;
}

} // namespace

CommandRunner addChartCommand(CLI::App& app)
{
    CLI::App* chart = app.add_subcommand("chart", "Charts of flight physics");
    chart->require_subcommand(1);
    auto args = std::make_shared<RangeArgs>();
    CLI::App* cmd = chart->add_subcommand("range", "Range on flat ground against launch angle, and the best angle");
    cmd->add_option("--speed", args->speed, "launch speed in m/s")->required();
    cmd->add_option("--y0", args->y0,
                    "launch height above the ground in m (default 0); ranges are to the ground (y = 0), not back to "
                    "the launch height as in predict --y0");
    addFlightModelOptions(*cmd, args->model);
    cmd->add_option("--from", args->from, "first angle in degrees (default -90)");
    cmd->add_option("--to", args->to, "last angle in degrees (default 90)");
    cmd->add_option("--step", args->step, "angle step in degrees (default 1)");
    cmd->add_option("--max-t", args->maxT, "a flight not down by then has no range (default 60 s)");
    cmd->add_option("--dt", args->dt, "RK4 step in s (default 1/60)");
    cmd->add_option("--out", args->out, "also draw the chart into this PNG file");
    cmd->add_flag("--json", args->json, "print one JSON object");

    auto tableArgs = std::make_shared<TableArgs>();
    CLI::App* table = chart->add_subcommand("table", "A CSV file (simulate --csv, the game's export) drawn as a "
                                                     "spreadsheet shows it, into a PNG");
    table->add_option("csv", tableArgs->csv, "the CSV file")->required();
    table->add_option("--out", tableArgs->out, "the PNG file to write")->required();
    table->add_option("--rows", tableArgs->rows, "data rows to show (default 20)");
    table->add_option("--every", tableArgs->every, "show every Nth data row (default 1)");
    return [args, tableArgs, table]
    {
        return table->parsed() ? runTable(*tableArgs) : runRange(*args);
    };
}

} // namespace abalike::app

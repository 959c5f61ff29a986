#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"
#include "shell/SessionJson.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/teach/ShotFeedback.hpp>
#include <abalike/teach/ShotTable.hpp>

#include <iostream>
#include <memory>

namespace abalike::app
{

namespace
{

struct SimulateArgs
{
    std::string level;
    std::vector<std::string> shots;
    bool json = false;
    std::string csv;
    std::string wording;
};

int runSimulate(const SimulateArgs& a)
{
    std::vector<ScriptedShot> shots;
    for (const std::string& text : a.shots)
        shots.push_back(parseShot(text));
    const bool university = parseWordingOption(a.wording).value_or(Wording::School) == Wording::University;
    const LevelDef level = loadLevel(a.level, Catalog::builtin());
    std::unique_ptr<GameSession> session;
    try
    {
        session = simulateShots(level, shots);
    }
    catch (const LaunchError& e)
    {
        throw UsageError(a.level + ": " + e.what());
    }
    if (!a.csv.empty())
    {
        try
        {
            writeFileAtomically(a.csv, shotTableCsv(*session));
        }
        catch (const std::exception& e)
        {
            throw UsageError("--csv " + a.csv + ": cannot write the file (" + e.what() + ")");
        }
    }
    if (a.json)
    {
        std::cout << sessionToJson(*session).dump() << '\n';
        return 0;
    }
    const ScoreBreakdown score = session->score();
    std::cout << level.id << " \"" << level.title << "\": "
              << (session->phase() == Phase::Won    ? "won"
                  : session->phase() == Phase::Lost ? "lost"
                                                    : "not finished")
              << ", score " << score.total() << ", " << session->stars() << " star(s), " << session->pigsRemaining()
              << " pig(s) left, " << session->birdsUsed() << " bird(s) used\n";
    for (std::size_t i = 0; i < session->shots().size(); ++i)
    {
        const ShotRecord& shot = session->shots()[i];
        std::cout << "  shot " << i + 1 << " (" << shot.bird << ", " << shot.angleDeg << " deg, " << shot.speedMps
                  << " m/s): ";
        if (shot.deviationM)
            std::cout << "first contact at (" << shot.actualContact->x << ", " << shot.actualContact->y
                      << "), predicted-actual " << *shot.deviationM * 1000.0 << " mm\n";
        else if (shot.actualContact)
            std::cout << "first contact at (" << shot.actualContact->x << ", " << shot.actualContact->y << ")"
                      << (shot.launchedIntoMovingWorld ? ", launched while blocks still moved: no deviation scored"
                                                       : "")
                      << "\n";
        else
            std::cout << "no contact\n";
        for (const std::string& sentence : shotFeedback(level, Catalog::builtin(), shot))
            std::cout << "    " << sentence << '\n';
        if (university && shot.actualContact)
            std::cout << "    Method: the preview and the world integrate the flight with the same RK4 steps of "
                      << session->world().dt() << " s; the preview casts each step's chord against the level (Box2D "
                      << "TOI), and the world hands the bird to Box2D at the first contact.\n";
    }
    return 0;
}

} // namespace

CommandRunner addSimulateCommand(CLI::App& app)
{
    auto args = std::make_shared<SimulateArgs>();
    CLI::App* cmd = app.add_subcommand("simulate", "Play shots on a level headless and report the outcome");
    cmd->add_option("level", args->level, "level JSON file")->required();
    cmd->add_option("--shot", args->shots,
                    "ANGLE,SPEED[,ABILITY_AT_S] (degrees, m/s, s after launch to use the bird's ability); repeat for "
                    "more shots")
        ->required()
        ->allow_extra_args(false);
    cmd->add_flag("--json", args->json, "print one JSON object");
    addWordingOption(*cmd, args->wording);
    cmd->add_option("--csv", args->csv,
                    "also write every shot's flight to FILE: one row per 1/60 s (shot, t, x, y, v, a, speed, kinetic "
                    "and potential energy, work against drag), for a spreadsheet");
    return [args]
    {
        return runSimulate(*args);
    };
}

} // namespace abalike::app

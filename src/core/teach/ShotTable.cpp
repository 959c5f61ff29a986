#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/FlightEnergy.hpp>
#include <abalike/teach/ShotTable.hpp>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace abalike
{

namespace
{

/// What the bird touched in a step, for the contact column: "block 3 wood", "pig 0 small", "ground", joined by
/// " + " (never a comma: it is one cell).
std::string touchedNames(const LevelDef& level, const std::vector<BodyRef>& touched)
{
    std::string text;
    for (const BodyRef& ref : touched)
    {
        if (!text.empty())
            text += " + ";
        text += entityKindName(ref.kind);
        if (ref.kind == EntityKind::Ground || ref.index < 0)
            continue;
        text += ' ';
        text += std::to_string(ref.index);
        const auto index = static_cast<std::size_t>(ref.index);
        if (ref.kind == EntityKind::Block && index < level.blocks.size())
            text.append(" ").append(level.blocks[index].material);
        else if (ref.kind == EntityKind::Pig && index < level.pigs.size())
            text.append(" ").append(level.pigs[index].type);
    }
    return text;
}

} // namespace

std::string shotTableCsv(const GameSession& session)
{
    std::ostringstream csv;
    csv << "shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j,contact,"
           "contact_acts\n";
    csv << std::setprecision(10);
    const double dt = session.world().dt();
    const double g = session.level().environment.gravity;
    for (std::size_t k = 0; k < session.shots().size(); ++k)
    {
        const ShotRecord& shot = session.shots()[k];
        const BirdType* bird = session.catalog().findBird(shot.bird);
        if (bird == nullptr)
            continue;
        // One point per step: the path also holds the moment of first contact, between two steps, whose touch
        // goes to the step it happened in.
        std::vector<TrackPoint> path;
        std::vector<std::vector<BodyRef>> touches;
        std::vector<BodyRef> pending;
        for (std::size_t p = 0; p < shot.actualPath.size(); ++p)
        {
            const auto& point = shot.actualPath[p];
            if (p < shot.actualTouches.size())
                for (const BodyRef& ref : shot.actualTouches[p])
                    if (std::find(pending.begin(), pending.end(), ref) == pending.end())
                        pending.push_back(ref);
            if (std::abs(point.timeS / dt - std::round(point.timeS / dt)) >= 1e-6)
                continue;
            path.push_back(point);
            touches.push_back(std::move(pending));
            pending.clear();
        }
        IntegratorSettings settings;
        settings.dtS = dt;
        const FlightModel flightModel = levelFlightModel(session.level().environment, *bird);
        const FlightIntegrator model(flightModel, settings);
        // Until its first contact the bird rides the RK4 states (the world flies exactly those steps), so the rows
        // up to then come from the replayed flight in double precision: exact velocity, acceleration and drag work,
        // free of the float rounding that central differences of the world's positions amplify (a few mm/s^2).
        // An ability that changed the flight ends the replay's validity where it fired.
        double replayUntil = -1.0;
        for (const auto& point : shot.actualPath)
            if (std::abs(point.timeS / dt - std::round(point.timeS / dt)) >= 1e-6)
            {
                replayUntil = point.timeS;
                break;
            }
        if (replayUntil < 0.0 && !shot.actualPath.empty())
            replayUntil = shot.actualPath.back().timeS;
        if (shot.ability && shot.ability->changedFlight)
            replayUntil = std::min(replayUntil, shot.ability->tS);
        std::optional<FlightEnergyTracker> replay;
        if (!shot.actualPath.empty() && replayUntil > 0.0)
        {
            const double angle = shot.angleDeg * 3.14159265358979323846 / 180.0;
            replay.emplace(flightModel, settings,
                           FlightState{{shot.actualPath.front().position.x, shot.actualPath.front().position.y},
                                       {shot.speedMps * std::cos(angle), shot.speedMps * std::sin(angle)}});
        }
        const double m = bird->massKg;
        double dragWork = 0.0;
        double lastDragPower = 0.0;
        double lastVx = 0.0;
        double lastVy = 0.0;
        // A row's differences span the steps ending at rows i - 1, i and i + 1: a contact in any of them acts on
        // the row's velocity and acceleration.
        const auto touchedIn = [&touches](std::size_t row)
        {
            return row < touches.size() && !touches[row].empty();
        };
        const auto contactActs = [&](std::size_t row)
        {
            return touchedIn(row) || (row > 0 && touchedIn(row - 1)) || touchedIn(row + 1);
        };
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            const bool exact = replay && path[i].timeS <= replayUntil + 1e-9;
            // A row past the replay needs the step after it for its central difference: the table (an export made
            // in flight too) ends at the last whole step instead of a one-sided half step.
            if (!exact && i > 0 && i + 1 >= path.size())
                break;
            const std::size_t a = i == 0 ? 0 : i - 1;
            const std::size_t b = i + 1 < path.size() ? i + 1 : i;
            const double span = path[b].timeS - path[a].timeS;
            double vx = span > 0 ? (path[b].position.x - path[a].position.x) / span : 0.0;
            double vy = span > 0 ? (path[b].position.y - path[a].position.y) / span : 0.0;
            if (i == 0)
            {
                // The launch velocity is known exactly.
                const double angle = shot.angleDeg * 3.14159265358979323846 / 180.0;
                vx = shot.speedMps * std::cos(angle);
                vy = shot.speedMps * std::sin(angle);
            }
            // The measured acceleration: the change of the velocity column over the step that ends at this row, so
            // that a row through a collision carries it and a spreadsheet's dv/dt agrees with the column.
            double ax = 0.0;
            double ay = 0.0;
            if (i > 0)
            {
                const double step = path[i].timeS - path[i - 1].timeS;
                ax = step > 0 ? (vx - lastVx) / step : 0.0;
                ay = step > 0 ? (vy - lastVy) / step : 0.0;
            }
            double x = path[i].position.x;
            double y = path[i].position.y;
            const bool acts = !exact && contactActs(i);
            if (exact)
            {
                const FlightEnergy e = replay->at(path[i].timeS);
                x = e.state.position.x;
                y = e.state.position.y;
                vx = e.state.velocity.x;
                vy = e.state.velocity.y;
                const FlightState rate = model.rightHandSide(path[i].timeS, e.state);
                ax = rate.velocity.x;
                ay = rate.velocity.y;
                dragWork = e.dragLossJ;
            }
            // The air's force on the bird: the model's acceleration less gravity; its power against the motion.
            const FlightState s{{x, y}, {vx, vy}};
            const FlightState rate = model.rightHandSide(path[i].timeS, s);
            if (!exact && !acts)
            {
                // In free flight after a contact (a bounce, a fall) the world flies the same model: its acceleration,
                // not a difference of float positions (-9.8098 for -9.81).
                ax = rate.velocity.x;
                ay = rate.velocity.y;
            }
            const double dragPower = -m * (rate.velocity.x * vx + (rate.velocity.y + g) * vy);
            if (i > 0 && !exact)
                dragWork += 0.5 * (dragPower + lastDragPower) * (path[i].timeS - path[i - 1].timeS);
            lastDragPower = dragPower;
            const double speed = std::hypot(vx, vy);
            lastVx = vx;
            lastVy = vy;
            csv << k + 1 << ',' << path[i].timeS << ',' << x << ',' << y << ',' << vx << ',' << vy << ',' << ax << ','
                << ay << ',' << speed << ',' << 0.5 * m * speed * speed << ',' << m * g * y << ',' << dragWork << ','
                << touchedNames(session.level(), touches[i]) << ',' << (acts ? 1 : 0) << '\n';
        }
    }
    return csv.str();
}

} // namespace abalike

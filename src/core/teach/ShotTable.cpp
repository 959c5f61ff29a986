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

std::string shotTableCsv(const GameSession& session)
{
    std::ostringstream csv;
    csv << "shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j\n";
    csv << std::setprecision(10);
    const double dt = session.world().dt();
    const double g = session.level().environment.gravity;
    for (std::size_t k = 0; k < session.shots().size(); ++k)
    {
        const ShotRecord& shot = session.shots()[k];
        const BirdType* bird = session.catalog().findBird(shot.bird);
        if (bird == nullptr)
            continue;
        // One point per step: the path also holds the moment of first contact, between two steps.
        std::vector<std::array<double, 3>> path;
        for (const auto& point : shot.actualPath)
            if (std::abs(point[0] / dt - std::round(point[0] / dt)) < 1e-6)
                path.push_back(point);
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
            if (std::abs(point[0] / dt - std::round(point[0] / dt)) >= 1e-6)
            {
                replayUntil = point[0];
                break;
            }
        if (replayUntil < 0.0 && !shot.actualPath.empty())
            replayUntil = shot.actualPath.back()[0];
        if (shot.ability && shot.ability->changedFlight)
            replayUntil = std::min(replayUntil, shot.ability->tS);
        std::optional<FlightEnergyTracker> replay;
        if (!shot.actualPath.empty() && replayUntil > 0.0)
        {
            const double angle = shot.angleDeg * 3.14159265358979323846 / 180.0;
            replay.emplace(flightModel, settings,
                           FlightState{shot.actualPath.front()[1], shot.actualPath.front()[2],
                                       shot.speedMps * std::cos(angle), shot.speedMps * std::sin(angle)});
        }
        const double m = bird->massKg;
        double dragWork = 0.0;
        double lastDragPower = 0.0;
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            const std::size_t a = i == 0 ? 0 : i - 1;
            const std::size_t b = i + 1 < path.size() ? i + 1 : i;
            const double span = path[b][0] - path[a][0];
            double vx = span > 0 ? (path[b][1] - path[a][1]) / span : 0.0;
            double vy = span > 0 ? (path[b][2] - path[a][2]) / span : 0.0;
            if (i == 0)
            {
                // The launch velocity is known exactly.
                const double angle = shot.angleDeg * 3.14159265358979323846 / 180.0;
                vx = shot.speedMps * std::cos(angle);
                vy = shot.speedMps * std::sin(angle);
            }
            double ax = 0.0;
            double ay = 0.0;
            if (i > 0 && i + 1 < path.size())
            {
                ax = (path[i + 1][1] - 2.0 * path[i][1] + path[i - 1][1]) / (dt * dt);
                ay = (path[i + 1][2] - 2.0 * path[i][2] + path[i - 1][2]) / (dt * dt);
            }
            double x = path[i][1];
            double y = path[i][2];
            const bool exact = replay && path[i][0] <= replayUntil + 1e-9;
            if (exact)
            {
                const FlightEnergy e = replay->at(path[i][0]);
                x = e.state[0];
                y = e.state[1];
                vx = e.state[2];
                vy = e.state[3];
                const FlightState rate = model.rightHandSide(path[i][0], e.state);
                ax = rate[2];
                ay = rate[3];
                dragWork = e.dragLossJ;
            }
            // The air's force on the bird: the model's acceleration less gravity; its power against the motion.
            const FlightState s{x, y, vx, vy};
            const FlightState rate = model.rightHandSide(path[i][0], s);
            const double dragPower = -m * (rate[2] * vx + (rate[3] + g) * vy);
            if (i > 0 && !exact)
                dragWork += 0.5 * (dragPower + lastDragPower) * (path[i][0] - path[i - 1][0]);
            lastDragPower = dragPower;
            const double speed = std::hypot(vx, vy);
            csv << k + 1 << ',' << path[i][0] << ',' << x << ',' << y << ',' << vx << ',' << vy << ',' << ax << ','
                << ay << ',' << speed << ',' << 0.5 * m * speed * speed << ',' << m * g * y << ',' << dragWork << '\n';
        }
    }
    return csv.str();
}

} // namespace abalike

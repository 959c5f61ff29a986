#include "teach/BirdReadout.hpp"

namespace abalike::app
{

bool ShotFollower::follow(const GameSession& session)
{
    if (session.shots().empty())
    {
        m_shotCount = 0;
        m_tracker.reset();
        return false;
    }
    const ShotRecord& shot = session.shots().back();
    if (m_tracker && m_shotCount == session.shots().size() && m_angleDeg == shot.angleDeg &&
        m_speedMps == shot.speedMps)
        return true;
    const BirdType* bird = session.catalog().findBird(shot.bird);
    if (bird == nullptr)
        return false;
    m_shotCount = session.shots().size();
    m_angleDeg = shot.angleDeg;
    m_speedMps = shot.speedMps;
    m_model = session.flightModelFor(*bird);
    const auto p = session.launchPoint();
    m_launch = launchState(p.x, p.y, shot.speedMps, shot.angleDeg);
    IntegratorSettings settings;
    settings.dtS = session.world().dt();
    m_tracker = std::make_unique<FlightEnergyTracker>(*m_model, settings, m_launch);
    return true;
}

std::optional<BirdReadout> ShotFollower::current(const GameSession& session)
{
    if (session.phase() != Phase::Flying || !session.world().birdInFreeFlight() || !follow(session))
        return std::nullopt;
    // An ability that changed the flight re-seeded the world's integrator: the replay no longer matches it.
    const ShotRecord& shot = session.shots().back();
    if (shot.ability && shot.ability->changedFlight)
        return std::nullopt;
    return at(session, session.timeSinceLaunch());
}

std::optional<BirdReadout> ShotFollower::at(const GameSession& session, double tS)
{
    if (!follow(session))
        return std::nullopt;
    BirdReadout r;
    r.tS = tS;
    r.energy = m_tracker->at(tS);
    r.state = r.energy.state;
    r.massKg = m_model->massKg;
    // The right-hand side less gravity is the air's force: one drag, on the velocity relative to the air. (Splitting
    // it into "still-air drag" and "wind" by difference would invent a wind force, with a vertical part for a
    // horizontal wind, because quadratic drag does not add.)
    const FlightIntegrator full(*m_model, {});
    const FlightState f = full.rightHandSide(tS, r.state);
    const double m = m_model->massKg;
    const double g = m_model->gravity;
    r.accelerationMps2 = {f.velocity.x, f.velocity.y};
    r.gravityN = {0.0, -m * g};
    r.dragN = {m * f.velocity.x, m * (f.velocity.y + g)};
    Vec2 wind{m_model->windX, m_model->windY};
    if (m_model->gusts)
    {
        const Vec2 gust = m_model->gusts->windAt(tS);
        wind = {wind.x + gust.x, wind.y + gust.y};
    }
    r.airVelocityMps = {r.state.velocity.x - wind.x, r.state.velocity.y - wind.y};
    r.windy = wind.x != 0.0 || wind.y != 0.0;
    return r;
}

} // namespace abalike::app

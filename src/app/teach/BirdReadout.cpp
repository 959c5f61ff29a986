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
    m_stillAir = m_model;
    m_stillAir->windX = m_stillAir->windY = 0.0;
    m_stillAir->gusts.reset();
    const auto p = session.launchPoint();
    m_launch = launchState(p[0], p[1], shot.speedMps, shot.angleDeg);
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
    // One right-hand side for the whole force, one without the wind: their difference is the wind's share.
    const FlightIntegrator full(*m_model, {});
    const FlightIntegrator still(*m_stillAir, {});
    const FlightState f = full.rightHandSide(tS, r.state);
    const FlightState fs = still.rightHandSide(tS, r.state);
    const double m = m_model->massKg;
    const double g = m_model->gravity;
    r.accelerationMps2 = {f[2], f[3]};
    r.gravityN = {0.0, -m * g};
    r.dragN = {m * fs[2], m * (fs[3] + g)};
    r.windN = {m * (f[2] - fs[2]), m * (f[3] - fs[3])};
    return r;
}

} // namespace abalike::app

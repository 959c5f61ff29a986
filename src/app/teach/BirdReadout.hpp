#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/teach/FlightEnergy.hpp>
#include <array>
#include <memory>
#include <optional>

namespace abalike::app
{

/// The physics of the flying bird at one moment, as the teaching overlay shows it: every force on its own.
struct BirdReadout
{
    double tS = 0.0;     ///< since launch
    FlightState state{}; ///< on the RK4 path the world flies the bird along
    double massKg = 0.0;
    Vec2 accelerationMps2{};
    Vec2 gravityN{};
    /// The air's whole force: drag on the velocity relative to the air, v - w. Wind has no force of its own; it
    /// acts only by moving the air the drag is measured against.
    Vec2 dragN{};
    Vec2 airVelocityMps{}; ///< v - w: the bird's velocity relative to the air
    bool windy = false;    ///< the air moves (w is not zero at this moment)
    FlightEnergy energy;
};

/// Follows the current shot: replays its RK4 flight (the same steps the world takes) to give the bird's state,
/// forces and energy balance at any time before its first contact.
class ShotFollower
{
public:
    /// The readout at the session's current time, while the latest shot's bird flies free; nullopt otherwise.
    std::optional<BirdReadout> current(const GameSession& session);
    /// The readout of the latest shot at time t since launch (t at most the first contact), if there is a shot.
    std::optional<BirdReadout> at(const GameSession& session, double tS);
    /// The flight model of the latest shot's bird (null before the first shot).
    const FlightModel* model() const { return m_model ? &*m_model : nullptr; }
    /// Launch state of the latest shot.
    const FlightState& launch() const { return m_launch; }
    /// Forgets the shot (a level started or restarted).
    void reset() { m_tracker.reset(); }

private:
    /// Starts following the latest shot if it is new; false if there is none.
    bool follow(const GameSession& session);

    std::size_t m_shotCount = 0;
    double m_angleDeg = 0.0;
    double m_speedMps = 0.0;
    std::optional<FlightModel> m_model;
    FlightState m_launch{};
    std::unique_ptr<FlightEnergyTracker> m_tracker;
};

} // namespace abalike::app

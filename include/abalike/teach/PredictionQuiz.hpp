#pragma once

#include <abalike/game/GameSession.hpp>
#include <optional>

namespace abalike
{

/// "Predict, then launch": the student predicts one number of the flight for the aim shown, launches, and compares
/// the prediction with what the world measured and with the closed form of projectile motion in vacuum.
enum class QuizQuantity
{
    Range,      ///< horizontal distance from the launch to where the bird's centre comes back to the launch height (m)
    MaxHeight,  ///< highest point of the bird's centre above the launch height (m)
    FlightTime, ///< time from launch until the bird's centre comes back to the launch height (s)
};

/// "range", "maximum height", "flight time".
const char* quizQuantityName(QuizQuantity quantity);
/// "m" or "s".
const char* quizQuantityUnit(QuizQuantity quantity);

/// A launch at speed v and angle a in vacuum, measured where the bird's centre comes back down to the height it was
/// launched from: the convention of `abalike predict` (and, at the ground line, of the range chart), and the
/// textbook's:
///   flight time  T = 2 v sin a / g
///   range        R = v cos a T = v^2 sin 2a / g
///   max height   H = v^2 sin^2 a / (2 g)   (above the launch)
struct QuizLaunch
{
    double speedMps = 0.0;
    double angleDeg = 0.0;
    double gravity = 9.81;
};

/// The closed form of the quantity; nullopt without gravity, or for range and time when the launch does not point
/// upwards (the bird never comes back to its launch height).
std::optional<double> closedFormAnswer(QuizQuantity quantity, const QuizLaunch& launch);

/// The quantity measured on the path the bird really flew (ShotRecord::actualPath): where (and when) its centre comes
/// back down through the launch point's height, interpolated between the physics steps around it. nullopt when it
/// touched something before that, or never came back down.
std::optional<double> measuredAnswer(QuizQuantity quantity, const ShotRecord& shot, Vec2 launchPoint);

} // namespace abalike

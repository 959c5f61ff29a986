#pragma once

#include <abalike/game/GameSession.hpp>
#include <optional>

namespace abalike
{

/// "Predict, then launch": the student predicts one number of the flight for the aim shown, launches, and compares
/// the prediction with what the world measured and with the closed form of projectile motion in vacuum.
enum class QuizQuantity
{
    Range,      ///< horizontal distance from the slingshot to where the bird first touches the ground (m)
    MaxHeight,  ///< highest point of the bird's centre above the ground (m)
    FlightTime, ///< time from launch until it first touches the ground (s)
};

/// "range", "maximum height", "flight time".
const char* quizQuantityName(QuizQuantity quantity);
/// "m" or "s".
const char* quizQuantityUnit(QuizQuantity quantity);

/// A launch from height h above flat ground at speed v and angle a in vacuum, ending when the bird's centre comes
/// down to height r above the ground (where a bird of radius r touches it):
///   flight time  T = (v sin a + sqrt(v^2 sin^2 a + 2 g (h - r))) / g
///   range        R = v cos a T
///   max height   H = h + v^2 sin^2 a / (2 g)   (h when the launch points down)
struct QuizLaunch
{
    double speedMps = 0.0;
    double angleDeg = 0.0;
    double gravity = 9.81;
    double launchHeightM = 0.0; ///< the bird's centre above the ground at launch
    double birdRadiusM = 0.0;
};

/// The closed form of the quantity; nullopt without gravity or when the flight never comes down to height r.
std::optional<double> closedFormAnswer(QuizQuantity quantity, const QuizLaunch& launch);

/// The quantity measured on the path the bird really flew (ShotRecord::actualPath), the touchdown interpolated
/// between the physics steps around it. launchX and groundY place the slingshot and the ground; nullopt when the
/// path never comes down to the ground (it hit something first, or the level ended).
std::optional<double> measuredAnswer(QuizQuantity quantity, const ShotRecord& shot, double launchX, double groundY,
                                     double birdRadiusM);

} // namespace abalike

#include <abalike/flight/StandardAtmosphere.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace abalike
{

namespace
{

/// U.S. Standard Atmosphere 1976 constants.
constexpr double kG0 = 9.80665;             // m/s^2, standard gravity
constexpr double kGasConstant = 287.052874; // J/(kg K): R* / M0 = 8.31432 / 0.0289644
constexpr double kEarthRadiusM = 6356766.0; // for geopotential altitude
constexpr double kSeaLevelTemperatureK = 288.15;
constexpr double kSeaLevelPressurePa = 101325.0;

/// A layer: base geopotential altitude (m) and its temperature lapse rate (K/m).
struct Layer
{
    double baseM;
    double lapseKPerM;
};

constexpr std::array<Layer, 7> kLayers{{
    {0.0, -0.0065},
    {11000.0, 0.0},
    {20000.0, 0.001},
    {32000.0, 0.0028},
    {47000.0, 0.0},
    {51000.0, -0.0028},
    {71000.0, -0.002},
}};

} // namespace

double standardAtmosphereDensity(double altitudeM)
{
    if (!std::isfinite(altitudeM) || altitudeM < 0.0 || altitudeM > kMaxStandardAtmosphereAltitudeM)
        throw std::invalid_argument("altitude must be 0 to 86000 m for the standard atmosphere, got " +
                                    std::to_string(altitudeM));
    // The layers are defined in geopotential altitude, in which gravity is constant.
    const double h = kEarthRadiusM * altitudeM / (kEarthRadiusM + altitudeM);
    double temperature = kSeaLevelTemperatureK;
    double pressure = kSeaLevelPressurePa;
    for (std::size_t i = 0; i < kLayers.size(); ++i)
    {
        const Layer& layer = kLayers[i];
        const double top = i + 1 < kLayers.size() ? kLayers[i + 1].baseM : h;
        const double dh = std::min(h, top) - layer.baseM;
        if (layer.lapseKPerM == 0.0)
            pressure *= std::exp(-kG0 * dh / (kGasConstant * temperature));
        else
        {
            const double next = temperature + layer.lapseKPerM * dh;
            pressure *= std::pow(temperature / next, kG0 / (kGasConstant * layer.lapseKPerM));
            temperature = next;
        }
        if (h <= top)
            break;
    }
    return pressure / (kGasConstant * temperature);
}

} // namespace abalike

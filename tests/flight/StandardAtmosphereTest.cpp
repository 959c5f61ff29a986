#include <abalike/flight/GravityPresets.hpp>
#include <abalike/flight/StandardAtmosphere.hpp>

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace abalike
{
namespace
{

TEST(StandardAtmosphere, MatchesTheUsStandardAtmosphere1976Table)
{
    // U.S. Standard Atmosphere 1976, table I (geometric altitude, kg/m^3).
    const struct
    {
        double altitudeM;
        double density;
    } table[] = {{0, 1.2250},        {1000, 1.1117},     {2000, 1.0066},     {5000, 0.73643},    {11000, 0.36480},
                 {15000, 0.19476},   {20000, 0.088910},  {30000, 0.018410},  {40000, 0.0039957}, {50000, 0.0010269},
                 {60000, 3.0968e-4}, {70000, 8.2829e-5}, {80000, 1.8458e-5}, {86000, 6.958e-6}};
    for (const auto& row : table)
        EXPECT_NEAR(standardAtmosphereDensity(row.altitudeM), row.density, 1e-3 * row.density) << row.altitudeM;
}

TEST(StandardAtmosphere, FallsSteadilyWithAltitude)
{
    double previous = standardAtmosphereDensity(0.0);
    for (double h = 250.0; h <= 86000.0; h += 250.0)
    {
        const double rho = standardAtmosphereDensity(h);
        ASSERT_LT(rho, previous) << h;
        previous = rho;
    }
}

TEST(StandardAtmosphere, RefusesAltitudesItDoesNotCover)
{
    EXPECT_THROW(standardAtmosphereDensity(-1.0), std::invalid_argument);
    EXPECT_THROW(standardAtmosphereDensity(86001.0), std::invalid_argument);
    EXPECT_THROW(standardAtmosphereDensity(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(GravityPresets, NameTheFiveWorldsOfTheSandboxWithTheirAir)
{
    const auto presets = gravityPresets();
    ASSERT_EQ(presets.size(), 5u);
    EXPECT_EQ(presets[0].name, "Earth");
    EXPECT_EQ(presets[0].gravity, 9.81);
    double jupiter = 0.0;
    for (const GravityPreset& p : presets)
        if (p.name == "Jupiter")
            jupiter = p.gravity;
    EXPECT_EQ(jupiter, 24.79);
    // Each world brings its own air: Mars's is thin, the Moon has none, Titan's is thicker than Earth's.
    for (const GravityPreset& p : presets)
    {
        if (p.name == "Earth")
        {
            EXPECT_EQ(p.airDensity, 1.2);
        }
        else if (p.name == "Moon")
        {
            EXPECT_EQ(p.airDensity, 0.0);
        }
        else if (p.name == "Mars")
        {
            EXPECT_EQ(p.airDensity, 0.020);
        }
        else if (p.name == "Titan")
        {
            EXPECT_GT(p.airDensity, 1.2);
        }
    }
}

} // namespace
} // namespace abalike

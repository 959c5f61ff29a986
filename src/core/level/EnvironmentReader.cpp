#include "level/LevelSections.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <numbers>
#include <sstream>

namespace abalike
{

namespace
{

using json = nlohmann::json;

constexpr NumberRange kWind{-limits::kMaxWindMps, limits::kMaxWindMps, "m/s"};

/// [wx, wy] in m/s.
std::optional<std::array<double, 2>> readVector(LevelReader& r, const json& value, const std::string& pointer)
{
    if (!r.array(value, pointer, 2, 2, "components [x, y] in m/s"))
        return std::nullopt;
    const auto x = r.numberAt(value[0], pointer + "/0", kWind);
    const auto y = r.numberAt(value[1], pointer + "/1", kWind);
    if (!x || !y)
        return std::nullopt;
    return std::array<double, 2>{*x, *y};
}

std::optional<GustDef> readGustSteps(LevelReader& r, const json& steps)
{
    const std::string p = "/environment/gusts";
    if (!r.array(steps, p, 1, limits::kMaxGustSteps, "gust steps"))
        return std::nullopt;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Steps;
    bool ok = true;
    for (std::size_t i = 0; i < steps.size(); ++i)
    {
        const std::string q = p + "/" + std::to_string(i);
        if (!r.object(steps[i], q, {"t", "wx", "wy"}))
        {
            ok = false;
            continue;
        }
        GustDef::Step step;
        step.startS = r.number(steps[i], q, "t", 0.0, true, NumberRange{0.0, limits::kMaxGustTimeS, "s"});
        step.windX = r.number(steps[i], q, "wx", 0.0, false, kWind);
        step.windY = r.number(steps[i], q, "wy", 0.0, false, kWind);
        if (!gusts.steps.empty() && step.startS <= gusts.steps.back().startS)
        {
            std::ostringstream message;
            message << "gust steps must start in increasing time (expected t > " << gusts.steps.back().startS
                    << " s, got " << step.startS << " s)";
            r.error(q + "/t", message.str());
            ok = false;
        }
        gusts.steps.push_back(step);
    }
    return ok ? std::optional<GustDef>(gusts) : std::nullopt;
}

std::optional<GustDef> readGustSine(LevelReader& r, const json& sine)
{
    const std::string p = "/environment/gusts";
    if (!r.object(sine, p, {"amplitude", "period_s", "phase_deg"}))
        return std::nullopt;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Sine;
    const auto amplitude = sine.find("amplitude");
    if (amplitude == sine.end())
        r.error(p, "missing required key \"amplitude\" (expected [ax, ay] in m/s)");
    else if (const auto a = readVector(r, *amplitude, p + "/amplitude"))
    {
        gusts.amplitudeX = (*a)[0];
        gusts.amplitudeY = (*a)[1];
    }
    gusts.periodS =
        r.number(sine, p, "period_s", 1.0, true, NumberRange{limits::kMinGustPeriodS, limits::kMaxGustPeriodS, "s"});
    gusts.phaseRad = r.number(sine, p, "phase_deg", 0.0, false,
                              NumberRange{-limits::kMaxAngleDeg, limits::kMaxAngleDeg, "degrees"}) *
                     std::numbers::pi / 180.0;
    return gusts;
}

} // namespace

void readEnvironment(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("environment");
    if (it == root.end() || !r.object(*it, "/environment", {"gravity", "air_density", "wind", "gusts"}))
        return;
    const json& e = *it;
    EnvironmentDef& env = level.environment;
    env.gravity = r.number(e, "/environment", "gravity", 9.81, false, NumberRange{0.0, limits::kMaxGravity, "m/s^2"});
    env.airDensity =
        r.number(e, "/environment", "air_density", 0.0, false, NumberRange{0.0, limits::kMaxAirDensity, "kg/m^3"});
    if (const auto wind = e.find("wind"); wind != e.end())
    {
        if (const auto w = readVector(r, *wind, "/environment/wind"))
        {
            env.windX = (*w)[0];
            env.windY = (*w)[1];
        }
    }
    if (const auto gusts = e.find("gusts"); gusts != e.end())
    {
        if (gusts->is_array())
            env.gusts = readGustSteps(r, *gusts);
        else if (gusts->is_object())
            env.gusts = readGustSine(r, *gusts);
        else
            r.error("/environment/gusts",
                    "expected steps [{\"t\", \"wx\", \"wy\"}, ...] or a sine {\"amplitude\", \"period_s\", "
                    "\"phase_deg\"}, got " +
                        describeJsonType(*gusts));
    }
    // Wind acts on a bird only through drag; without air it would silently do nothing.
    if (env.airDensity <= 0.0)
        for (const char* key : {"wind", "gusts"})
            if (e.contains(key))
                r.error(std::string("/environment/") + key,
                        std::string(key) +
                            " acts only through air drag (expected \"air_density\" > 0 in "
                            "/environment, got " +
                            (e.contains("air_density") ? "0" : "none") + ")");
}

} // namespace abalike

#include <abalike/flight/Stepper.hpp>

#include <array>
#include <utility>

namespace abalike
{

namespace
{
constexpr std::array<std::pair<StepperKind, std::string_view>, 5> kStepperNames{{
    {StepperKind::Euler, "euler"},
    {StepperKind::SemiImplicitEuler, "semi-implicit-euler"},
    {StepperKind::Rk4, "rk4"},
    {StepperKind::Dopri5, "dopri5"},
    {StepperKind::Analytic, "analytic"},
}};
} // namespace

std::string_view stepperName(StepperKind kind)
{
    for (const auto& [k, name] : kStepperNames)
        if (k == kind)
            return name;
    return "unknown";
}

std::optional<StepperKind> parseStepper(std::string_view name)
{
    for (const auto& [k, n] : kStepperNames)
        if (n == name)
            return k;
    return std::nullopt;
}

} // namespace abalike

#include "teach/WhyPanel.hpp"

#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

namespace abalike::app
{

sf::FloatRect drawWhyPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topLeft,
                           const GameSession& session, const PredictedFlight* preview, unsigned titleSize,
                           unsigned rowSize, float scale)
{
    const GameWorld& world = session.world();
    std::vector<PanelRow> rows;
    rows.push_back({"Preview: RK4 steps of 1/60 s from the slingshot,", ""});
    rows.push_back({"each step's chord cast against the level (Box2D TOI)", ""});
    if (preview != nullptr)
        rows.push_back({"  this aim", std::to_string(preview->steps) + " steps, " +
                                          std::to_string(preview->rhsEvaluations) + " force evaluations"});
    rows.push_back({"World: the bird rides the same RK4 states until it", ""});
    rows.push_back({"touches something; then Box2D takes over", ""});
    if (session.phase() == Phase::Flying)
        rows.push_back({"  now", world.birdInFreeFlight()
                                     ? "t " + withUnit(session.timeSinceLaunch(), 2, "s") + ", on the RK4 path"
                                     : "Box2D owns the bird (" + std::to_string(world.lastSubsteps()) + " sub-step" +
                                           (world.lastSubsteps() > 1 ? "s)" : ")")});
    if (!session.shots().empty())
    {
        const ShotRecord& shot = session.shots().back();
        if (shot.deviationM)
            rows.push_back({"  last shot: predicted vs actual contact", formatDistance(*shot.deviationM)});
        else if (shot.ability && shot.ability->changedFlight)
            rows.push_back({"  last shot: its ability changed the flight", ""});
        else if (shot.launchedIntoMovingWorld)
        {
            // The preview was cast against the blocks where they were at launch; they moved on since.
            rows.push_back({"  last shot: launched while blocks still moved,", ""});
            rows.push_back({"  so it has no deviation and no accuracy points", ""});
        }
    }
    rows.push_back({"They part only if an ability changes the flight, above", ""});
    rows.push_back({"108 m/s (Box2D sub-steps), or by float rounding (\u00B5m)", ""});
    const TextPanel panel("Why preview and world can differ", std::move(rows));
    return panel.draw(target, font, topLeft, titleSize, rowSize, scale);
}

} // namespace abalike::app

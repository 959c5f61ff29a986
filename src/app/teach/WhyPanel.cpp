#include "teach/WhyPanel.hpp"

#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

namespace abalike::app
{

sf::FloatRect drawWhyPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topLeft,
                           const GameSession& session, const PredictedFlight* preview, bool university,
                           unsigned titleSize, unsigned rowSize, float scale)
{
    const GameWorld& world = session.world();
    std::vector<PanelRow> rows;
    if (university)
    {
        rows.push_back({"Preview: RK4 steps of 1/60 s from the slingshot,", ""});
        rows.push_back({"each step's chord cast against the level (Box2D TOI)", ""});
    }
    else
    {
        // School wording: the same facts without the machinery's names.
        rows.push_back({"Preview: the computer steps the flight forward", ""});
        rows.push_back({"1/60 s at a time and checks each step for a hit", ""});
    }
    if (preview != nullptr)
        rows.push_back(
            {"  this aim",
             std::to_string(preview->steps) + " steps" +
                 (university ? ", " + std::to_string(preview->rhsEvaluations) + " force evaluations" : std::string())});
    rows.push_back({university ? "World: the bird rides the same RK4 states until it"
                               : "World: the bird flies the very same steps until it",
                    ""});
    rows.push_back(
        {university ? "touches something; then Box2D takes over" : "touches something; then collisions take over", ""});
    if (session.phase() == Phase::Flying)
    {
        const std::string substeps =
            std::to_string(world.lastSubsteps()) + " sub-step" + (world.lastSubsteps() > 1 ? "s" : "");
        rows.push_back({"  now", world.birdInFreeFlight()
                                     ? "t " + withUnit(session.timeSinceLaunch(), 2, "s") + ", on the predicted path"
                                 : university ? "Box2D owns the bird (" + substeps + ")"
                                              : std::string("colliding")});
    }
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
    rows.push_back(
        {university ? "108 m/s (Box2D sub-steps), or by float rounding (\u00B5m)" : "108 m/s, or by rounding (\u00B5m)",
         ""});
    const TextPanel panel("Why preview and world can differ", std::move(rows));
    if (!fullPanelFits(target, {topLeft, panel.measure(font, titleSize, rowSize, scale)}, "why"))
    {
        const ShotRecord* last = session.shots().empty() ? nullptr : &session.shots().back();
        return drawPanelSummary(target, font, topLeft, false,
                                last != nullptr && last->deviationM
                                    ? "Preview and world: the last shot's contact " +
                                          formatDistance(*last->deviationM) + " apart"
                                    : std::string("Preview and world fly the same steps until a contact"),
                                rowSize, scale, "why");
    }
    return panel.draw(target, font, topLeft, titleSize, rowSize, scale);
}

} // namespace abalike::app

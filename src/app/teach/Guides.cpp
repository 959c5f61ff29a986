#include "teach/Guide.hpp"

#include "render/TextFormat.hpp"

#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/TextValues.hpp>

#include <cmath>

namespace abalike::app
{

namespace
{

bool angleChanged(const GuideContext& c)
{
    return c.aim && c.firstAim && std::abs(c.aim->angleDeg - c.firstAim->angleDeg) > 0.05; // one fine step is 0.1°
}

bool powerChanged(const GuideContext& c)
{
    return c.aim && c.firstAim && std::abs(c.aim->speedMps - c.firstAim->speedMps) > 0.05;
}

bool launched(const GuideContext& c)
{
    return c.shots() > c.shotsAtStepStart;
}

/// A shot launched during this step at an angle the test accepts.
template <class Test>
bool launchedAt(const GuideContext& c, Test accept)
{
    return launched(c) && accept(c.session->shots().back().angleDeg);
}

bool won(const GuideContext& c)
{
    return c.session->phase() == Phase::Won || c.session->pigsRemaining() == 0;
}

bool hitABody(const GuideContext& c)
{
    return !c.session->shots().empty() && c.session->shots().back().impact.has_value();
}

/// A shot launched during this step touched a pig first or defeated one (a miss does not count).
bool hitAPig(const GuideContext& c)
{
    if (!launched(c))
        return false;
    const ShotRecord& shot = c.session->shots().back();
    return shot.pigsDefeated > 0 || shot.firstTouched == EntityKind::Pig;
}

bool brokenMaterial(const GuideContext& c, const std::string& material)
{
    for (const Entity& e : c.session->world().entities())
        if (e.kind == EntityKind::Block && e.typeName == material && !e.alive)
            return true;
    return false;
}

GuideStep overlayStep(const std::string& why)
{
    return {"Press T for the teaching overlay: " + why, [](const GuideContext& c)
            {
                return c.overlayOn;
            }};
}

/// Heavy and light birds: the numbers come from the lesson's own slingshot and birds.
Guide massLesson(const LevelDef& level, const Catalog& catalog)
{
    const BirdType* light = catalog.findBird("red");
    const BirdType* heavy = catalog.findBird("black");
    if (light == nullptr || heavy == nullptr)
        return {};
    const SlingshotBand lightBand = slingshotBand(level, *light, catalog);
    const SlingshotBand heavyBand = slingshotBand(level, *heavy, catalog);
    const double energy = lightBand.fullEnergyJ();
    const double vLight = lightBand.maxSpeedMps();
    const double vHeavy = heavyBand.maxSpeedMps();
    const double band = lightBand.bandMassKg();
    const auto kg = [](double m)
    {
        return formatFixed(m, 0) + " kg";
    };
    const auto mps = [](double v)
    {
        return formatFixed(v, 1) + " m/s";
    };
    const auto percent = [](double share)
    {
        return formatFixed(100.0 * share, 0) + " %";
    };
    return {"Lesson: heavy and light birds",
            {{"Pull all the way and launch the red bird (" + kg(light->massKg) +
                  "). The aim panel shows the band's pull, its force, the energy E = \u00BD F x it stores, the bird's "
                  "share "
                  "of it and v\u2080 = \u221A(2E / (m + m_b)): the band's pouch and rubber (m_b = " +
                  kg(band) + ") fly forward with the bird.",
              launched},
             {"The black bird weighs " + kg(heavy->massKg) + ". Launch it at full pull too: the same " +
                  formatFixed(energy, 0) + " J now moves " + kg(heavy->massKg + band) + " instead of " +
                  kg(light->massKg + band) + ", so it leaves at " + mps(vHeavy) + " instead of " + mps(vLight) +
                  " (\u221A(" + kg(light->massKg + band) + " / " + kg(heavy->massKg + band) +
                  ") = " + percent(vHeavy / vLight) + ") and takes " + percent(heavyBand.birdShare()) +
                  " of the energy, not " + percent(lightBand.birdShare()) + ".",
              launched},
             {"Nearly the same speed, twice the mass: the momentum p = m v\u2080 is " +
                  formatFixed(heavy->massKg * vHeavy, 0) + " N\u00B7s for the heavy bird and " +
                  formatFixed(light->massKg * vLight, 0) + " N\u00B7s for the light one. Knock out the pig.",
              won}},
            "Same pull, nearly the same speed: the band's own moving mass evens the birds out, so a heavy bird carries "
            "more momentum and more of the band's energy into what it hits."};
}

/// Materials: the strengths are the lesson level's own (its overrides applied), never typed.
Guide materialsLesson(const LevelDef& level, const Catalog& base)
{
    const Catalog catalog = levelCatalog(level, base);
    const auto strength = [&](const char* name)
    {
        const Material* material = catalog.findMaterial(name);
        return formatFixed(material != nullptr ? material->strengthNs : 0.0, 0) + " N\u00B7s";
    };
    return {"Lesson: materials",
            {overlayStep("the impact panel shows how much of a block's strength a hit used."),
             {"Break the ice column: ice gives way at " + strength("ice") + " of impulse.",
              [](const GuideContext& c)
              {
                  return brokenMaterial(c, "ice");
              }},
             {"Now the wood (" + strength("wood") + ") and the stone (" + strength("stone") +
                  "): no red bird's hit breaks stone, so topple it or go around it.",
              won}},
            "Strength and density decide what breaks: hit ice anywhere, wood hard, stone only when you must."};
}

/// Gravity: the lesson level's g against Earth's.
Guide gravityLesson(const LevelDef& level)
{
    const double g = level.environment.gravity;
    const std::string ratio = formatFixed(g > 0.0 ? kEarthGravity / g : 0.0, 1);
    return {"Lesson: gravity",
            {{"Press G: here g = " + formatFixed(g, 2) + " m/s\u00B2, so in vacuum every range is " + ratio +
                  " times as long as on Earth (R = v\u00B2 sin 2a / g).",
              [](const GuideContext& c)
              {
                  return c.chartOn;
              }},
             {"Launch at about 45\u00B0 with a gentle pull: the bird stays in the sky " + ratio +
                  " times as long as on Earth.",
              launched},
             {"Take out the pig.", won}},
            "Range and flight time both grow as 1/g: the same launch crosses " + ratio + " times the field here."};
}

Guide lesson(const std::string& id, const LevelDef& level, const Catalog& catalog)
{
    if (id == "lesson-angle")
        return {"Lesson: angle and range",
                {{"Press G: the chart shows how far this bird lands at every angle, at the pull you have now.",
                  [](const GuideContext& c)
                  {
                      return c.chartOn;
                  }},
                 {"Pull all the way back (\u2192 or a long drag), then launch at 30\u00B0 or lower.",
                  [](const GuideContext& c)
                  {
                      return launchedAt(c, [](double a) { return a <= 32.0; });
                  }},
                 {"Now launch at 60\u00B0 or higher: nearly the same range, because sin 2\u03B8 is the same for \u03B8 "
                  "and 90\u00B0 \u2212 \u03B8.",
                  [](const GuideContext& c)
                  {
                      return launchedAt(c, [](double a) { return a >= 58.0; });
                  }},
                 {"Throw the bird onto the pig at full pull: only angles near the chart's ring get there.", won}},
                "In vacuum from the ground 45\u00B0 throws farthest. From a height, or in air, a little lower wins: "
                "try G on the other levels."};
    if (id == "lesson-mass")
        return massLesson(level, catalog);
    if (id == "lesson-drag")
        return {
            "Lesson: air drag",
            {overlayStep("arrows for every force, bars for the energy."),
             {"Launch, and watch the orange drag arrow: it points against the motion and shrinks as the bird slows.",
              launched},
             {"The orange bar is the energy the air took, for good. Hit the tower: the line under the shot says how "
              "far the bird would have flown in vacuum.",
              won}},
            "Drag grows with the square of the speed: the faster the shot, the bigger the share the air takes."};
    if (id == "lesson-wind")
        return {
            "Lesson: wind",
            {overlayStep("the green arrow is the bird's velocity through the air, v \u2212 w."),
             {"Launch into the headwind. The wind has no force of its own: drag points against v \u2212 w, and "
              "against the wind that is a bigger push.",
              launched},
             {"Press G: the range chart includes the wind. Find an angle that still reaches the tower.",
              [](const GuideContext& c)
              {
                  return c.chartOn;
              }},
             {"Take out the pig: pull harder than in still air. The chart's best angle is lower, not higher.", won}},
            "A headwind shortens every shot and favours flatter ones; a tailwind carries high, slow shots."};
    if (id == "lesson-momentum")
        return {"Lesson: momentum and energy",
                {overlayStep("after the first impact a panel shows momentum and energy."),
                 {"Hit the big wood block.", hitABody},
                 {"Read the impact panel: the impulse bird and block pushed each other with, both changes of momentum, "
                  "what "
                  "the block stands on pushed, the kinetic energy lost (to heat, sound and deformation), and the "
                  "impulse the block took against its strength. Then take out the pig.",
                  won}},
                "Momentum is shared in a collision; kinetic energy is not kept. In this game a block breaks when the "
                "impulse it takes (N\u00B7s) reaches its strength: a rule of the game, not of energy."};
    if (id == "lesson-materials")
        return materialsLesson(level, catalog);
    if (id == "lesson-gravity")
        return gravityLesson(level);
    if (id == "lesson-predict")
        return {
            "Lesson: predict, then launch",
            {{"Read the aim in the card (angle and speed) and work out how far the bird flies until its centre is back "
              "at the launch height: R = v\u00B2 sin 2a / g. Type R in metres and press Enter; the preview shows "
              "once your prediction is locked.",
              [](const GuideContext& c)
              {
                  return c.predictionLocked || c.predictionsAnswered > 0;
              }},
             {"Launch at that aim (Space) and compare: your prediction, the flight, the formula.",
              [](const GuideContext& c)
              {
                  return c.predictionsAnswered > 0;
              }},
             {"Press Tab to predict the height it rises above the launch (H = v\u00B2 sin\u00B2 a / 2g) or the flight "
              "time (T = 2 v sin a / g) instead, then take out the pig.",
              won}},
            "The world flies the physics the formula describes: a good prediction lands within centimetres."};
    return {};
}

} // namespace

Guide tutorialGuide()
{
    return {"Tutorial: the controls",
            {{"Aim: drag the bird back from the slingshot with the mouse (the direction sets the angle), or press "
              "\u2191 and \u2193.",
              angleChanged},
             {"Pull: drag the bird further back, or press \u2192 and \u2190. The top panel shows how far the band is "
              "pulled, its force, the energy it stores and the launch speed that energy gives the bird.",
              powerChanged},
             {"The white dots are the preview: where the bird will fly. Let go of the mouse, or press Space, to "
              "launch.",
              launched},
             {"Press T (now or while it flies): arrows show the forces on the bird, bars its energy.",
              [](const GuideContext& c)
              {
                  return c.overlayOn;
              }},
             {"Point at any dot of a path to read its time, position and speed; drag with the right mouse button to "
              "measure a distance.",
              [](const GuideContext& c)
              {
                  return c.measured;
              }},
             {"Launch again and hit a pig (a miss keeps this step; R restarts with every bird). F1 lists every key.",
              hitAPig}},
            "That is every control. The campaign teaches the physics; the title menu has a short lesson on each idea."};
}

std::optional<Guide> guideFor(const LevelDef& level, const Catalog& catalog)
{
    const std::string& levelId = level.id;
    if (levelId == kTutorialId)
        return tutorialGuide();
    if (levelId.rfind("lesson-", 0) == 0)
    {
        Guide guide = lesson(levelId, level, catalog);
        if (!guide.steps.empty())
            return guide;
    }
    return std::nullopt;
}

const std::vector<LessonEntry>& lessonList()
{
    static const std::vector<LessonEntry> lessons{
        {"lesson-angle", "Angle and range", "lesson-angle.json"},
        {"lesson-mass", "Heavy and light birds", "lesson-mass.json"},
        {"lesson-drag", "Air drag", "lesson-drag.json"},
        {"lesson-wind", "Wind", "lesson-wind.json"},
        {"lesson-momentum", "Momentum and energy", "lesson-momentum.json"},
        {"lesson-materials", "Materials", "lesson-materials.json"},
        {"lesson-gravity", "Gravity", "lesson-gravity.json"},
        {"lesson-predict", "Predict, then launch", "lesson-predict.json"},
    };
    return lessons;
}

} // namespace abalike::app

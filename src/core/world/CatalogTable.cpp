#include <abalike/world/CatalogTable.hpp>

#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace abalike
{

namespace
{

/// A number with a fixed count of decimals.
std::string fixed(double value, int decimals)
{
    std::ostringstream out;
    out << std::fixed << std::setprecision(decimals) << value;
    return out.str();
}

std::string materialsTable(const Catalog& catalog)
{
    std::ostringstream md;
    md << "| Material | Bulk density (kg/m³) | Areal density (kg/m²) | Friction | Restitution | Strength (N s) | "
          "Points | Basis |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|\n";
    for (const Material& m : catalog.materials())
        md << "| " << m.name << " | " << fixed(m.bulkDensityKgPerM3, 0) << " | " << fixed(m.densityKgPerM2, 0) << " | "
           << fixed(m.friction, 2) << " | " << fixed(m.restitution, 2) << " | " << fixed(m.strengthNs, 0) << " | "
           << m.points << " | " << m.note << " |\n";
    return md.str();
}

/// The catalog's slingshot on Earth (a level with no world of its own), the band the tables show.
BandDef earthBand(const Catalog& catalog)
{
    return worldBand(LevelDef{}, catalog);
}

double fullPullSpeed(const Catalog& catalog, const BirdType& bird)
{
    return SlingshotBand(earthBand(catalog), bird.massKg, catalog.maxLaunchSpeedMps()).maxSpeedMps();
}

std::string birdsTable(const Catalog& catalog)
{
    std::ostringstream md;
    md << "| Bird | Mass (kg) | Radius (m) | Drag Cd | Friction | Restitution | Ability | v0 at full pull (m/s) |"
          " Momentum (N s) |\n"
       << "|---|---:|---:|---:|---:|---:|---|---:|---:|\n";
    for (const BirdType& b : catalog.birds())
    {
        const double v0 = fullPullSpeed(catalog, b);
        md << "| " << b.name << " | " << fixed(b.massKg, 1) << " | " << fixed(b.radiusM, 2) << " | "
           << fixed(b.dragCoefficient, 2) << " | " << fixed(b.friction, 2) << " | " << fixed(b.restitution, 2) << " | "
           << b.abilityName() << " | " << fixed(v0, 1) << " | " << fixed(b.massKg * v0, 0) << " |\n";
    }
    return md.str();
}

/// The same band, every bird: one stored energy, shared between the bird and the band's moving mass.
std::string launchTable(const Catalog& catalog)
{
    const BandDef band = earthBand(catalog);
    const double energy = 0.5 * band.maxForceN * band.maxPullM;
    std::ostringstream md;
    md << "| Bird | Mass (kg) | v0 = √(2E/(m + m_b)) | Momentum m·v0 | Bird's energy ½·m·v0² | Share m/(m + m_b) |\n"
       << "|---|---:|---:|---:|---:|---:|\n";
    for (const BirdType& b : catalog.birds())
    {
        const double v0 = fullPullSpeed(catalog, b);
        md << "| " << b.name << " | " << fixed(b.massKg, 1) << " | " << fixed(v0, 1) << " m/s | "
           << fixed(b.massKg * v0, 0) << " N·s | " << fixed(std::min(energy, 0.5 * b.massKg * v0 * v0), 0) << " J | "
           << fixed(100.0 * b.massKg / (b.massKg + band.bandMassKg), 0) << " % |\n";
    }
    return md.str();
}

std::string abilitiesTable(const Catalog& catalog)
{
    std::ostringstream md;
    md << "| Ability | Birds | Parameters | What it does |\n|---|---|---|---|\n";
    for (const auto& ability : catalog.abilities())
    {
        std::string birds;
        for (const BirdType& b : catalog.birds())
            if (b.ability == ability)
                birds += (birds.empty() ? "" : ", ") + b.name;
        md << "| " << ability->name() << " | " << (birds.empty() ? "none" : birds) << " | " << ability->parameters()
           << " | " << ability->description() << " |\n";
    }
    return md.str();
}

/// One line for a player: which bird has which ability.
std::string birdAbilities(const Catalog& catalog)
{
    std::string line;
    for (const BirdType& b : catalog.birds())
        if (b.ability)
            line += (line.empty() ? "" : ", ") + b.name + " bird: " + std::string(b.abilityName());
    return line.empty() ? "no bird has one" : line;
}

template <typename Kind>
std::string codeNames(const std::vector<Kind>& kinds)
{
    std::string line;
    for (const Kind& kind : kinds)
        line += (line.empty() ? "`" : ", `") + kind.name + "`";
    return line;
}

std::string birdNames(const Catalog& catalog)
{
    return codeNames(catalog.birds());
}

std::string materialNames(const Catalog& catalog)
{
    return codeNames(catalog.materials());
}

std::string pigsTable(const Catalog& catalog)
{
    std::ostringstream md;
    md << "| Pig | Radius (m) | Mass (kg) | Health (N s) | Points | Helmet |\n|---|---:|---:|---:|---:|---|\n";
    for (const PigType& p : catalog.pigs())
        md << "| " << p.name << " | " << fixed(p.radiusM, 2) << " | "
           << fixed(p.densityKgPerM2 * std::numbers::pi * p.radiusM * p.radiusM, 1) << " | " << fixed(p.healthNs, 0)
           << " | " << p.points << " | " << (p.helmet ? "yes" : "no") << " |\n";
    return md.str();
}

struct DocSection
{
    const char* name;
    std::string (*render)(const Catalog&);
};

constexpr DocSection kDocSections[] = {
    {"materials", materialsTable},     {"birds", birdsTable},
    {"launch", launchTable},           {"abilities", abilitiesTable},
    {"bird-abilities", birdAbilities}, {"pigs", pigsTable},
    {"bird-names", birdNames},         {"material-names", materialNames},
};

} // namespace

std::vector<std::string_view> catalogDocSectionNames()
{
    std::vector<std::string_view> names;
    for (const DocSection& section : kDocSections)
        names.emplace_back(section.name);
    return names;
}

std::optional<std::string> catalogDocSection(const Catalog& catalog, std::string_view name)
{
    for (const DocSection& section : kDocSections)
        if (name == section.name)
            return section.render(catalog);
    return std::nullopt;
}

std::string catalogMarkdown(const Catalog& catalog)
{
    std::ostringstream md;
    md << "# Materials, birds and pigs\n\n"
       << "Generated from `assets/catalog.json` (compiled into the core as `Catalog::builtin()`) by\n"
       << "`catalogMarkdown()`; `tests/world/CatalogTableTest.cpp` fails when this file is out of date, and\n"
       << "`tests/world/CatalogDocsTest.cpp` when a table or number another doc takes from the catalog is. "
          "Regenerate both with\n"
       << "`ABALIKE_UPDATE_DOCS=1 build/tests/abalike_tests --gtest_filter='Catalog*Docs*'`.\n\n"
       << "Box2D is 2D: every block is a slab " << fixed(catalog.slabDepthM(), 2)
       << " m deep, so its areal density (what Box2D uses) is the\n"
       << "bulk density times " << fixed(catalog.slabDepthM(), 2)
       << " m. Box2D mixes friction as sqrt(f1 f2) and restitution as max(e1, e2), and\n"
       << "applies restitution only above 1 m/s closing speed. Strength is the impulse a block absorbs before it "
          "breaks.\n\n";

    md << "## Materials\n\n" << materialsTable(catalog);

    md << "\n## Mass ratios (Box2D: stacking degrades past 10:1, heavy on light)\n\n"
       << "Mass of a block resting on a block of the same size, divided by the mass of the one under it:\n\n"
       << "| upper \\ lower |";
    for (const Material& lower : catalog.materials())
        md << ' ' << lower.name << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < catalog.materials().size(); ++i)
        md << "---:|";
    md << '\n';
    double worst = 0.0;
    for (const Material& upper : catalog.materials())
    {
        md << "| " << upper.name << " |";
        for (const Material& lower : catalog.materials())
        {
            const double ratio = upper.densityKgPerM2 / lower.densityKgPerM2;
            worst = std::max(worst, ratio);
            md << ' ' << fixed(ratio, 2) << " |";
        }
        md << '\n';
    }
    md << "\nWorst same-size ratio: " << fixed(worst, 2)
       << ". Blocks of different sizes multiply it by their area ratio; the level check\n"
       << "(`checkRest`) reports the worst heavy-on-light pair of every level, and the tests keep every campaign "
          "level and\n"
       << "stress scene at or below 10.\n\n";

    const BandDef band = earthBand(catalog);
    md << "## Birds\n\n"
       << "The slingshot's band is a linear spring whose pouch and rubber move with the bird: on Earth it pulls with "
       << fixed(band.maxForceN, 0) << " N at its full " << fixed(band.maxPullM, 1)
       << " m pull and stores E = 1/2 F x = " << fixed(0.5 * band.maxForceN * band.maxPullM, 0)
       << " J, which the bird and the band's\nmoving " << fixed(band.bandMassKg, 0)
       << " kg share: v0 = sqrt(2 E / (m + m_b)), so every bird leaves within 10 % of the red bird's speed and the "
          "heavy\nbirds carry more momentum (docs/slingshot.md).\n\n"
       << birdsTable(catalog);

    md << "\n## Abilities (click or Space in flight)\n\n" << abilitiesTable(catalog);
    md << "\n## Pigs\n\n" << pigsTable(catalog);

    const ScoringRules& s = catalog.scoring();
    md << "\n## Damage and scoring\n\n"
       << "- Damage: the normal impulses Box2D reports (PostSolve) of contacts closing faster than "
       << fixed(catalog.damageSpeedThresholdMps(), 1)
       << " m/s;\n  resting contact never hurts. Every body hurts what it "
          "hits by this rule: birds, falling blocks, pigs and the ground.\n"
       << "- Break-through: a block or pig whose remaining strength H is reached by the impulse J of a step breaks "
          "and\n"
          "  absorbs only H; whatever struck it gets the rest, J - H, back along the contact normal (a block that "
          "fails\n"
          "  cannot also stop the bird).\n";
    for (const Material& m : catalog.materials())
        if (m.blastRadiusM > 0.0)
            md << "- " << m.name
               << " explodes when it breaks: radial impulse J (1 - d/R), R = " << fixed(m.blastRadiusM, 1)
               << " m, J = " << fixed(m.blastImpulseNs, 0)
               << " N s, on every block and pig within R, absorbed as damage too; a crate it breaks explodes in "
                  "turn.\n";
    md << "- Points per destroyed block by material (above) and per pig by type.\n"
       << "- Efficiency: " << s.pointsPerUnusedBird << " per bird left when the level is won, and "
       << s.efficiencyPointsPerExtraPig << " per pig beyond the first\n  that one shot defeats.\n"
       << "- Accuracy: a shot whose first contact is a block or a pig, on the flight the preview predicted (no "
          "ability\n  fired before contact, launched into a calm world), earns "
       << s.accuracyPointsPerShot << " x max(0, 1 - deviation / " << fixed(s.accuracyToleranceM, 2) << " m).\n";
    return md.str();
}

} // namespace abalike

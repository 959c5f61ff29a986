#include <abalike/design/GeneratorLayouts.hpp>

#include "edit/EditHelpers.hpp"

#include <abalike/design/PartVariation.hpp>
#include <abalike/flight/GravityPresets.hpp>
#include <abalike/level/WorldTheme.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace abalike
{

namespace
{

/// Fewer bodies than this and a layout gets neighbours (the campaign asks 15 of its levels; parts come in threes).
constexpr int kMinBodies = 12;

/// The bounds of every block and pig of a level, as the editor selects them (objectBounds).
std::vector<std::array<Vec2, 2>> bodyBoxes(const LevelDef& level, const Catalog& catalog)
{
    std::vector<std::array<Vec2, 2>> boxes;
    for (const BlockDef& b : level.blocks)
        boxes.push_back(objectBounds(ObjectDef(b), catalog));
    for (const PigDef& p : level.pigs)
        boxes.push_back(objectBounds(ObjectDef(p), catalog));
    return boxes;
}

int bodiesOf(const LevelDef& level)
{
    return static_cast<int>(level.blocks.size() + level.pigs.size());
}

/// Heights in a part's upper two thirds that no block crosses and a plank or a block as wide as it is tall ends at:
/// where it can be cut and still end in a floor, not in bare posts.
std::vector<double> storeyLines(const LevelDef& part, const Catalog& catalog)
{
    std::vector<std::array<Vec2, 2>> blocks;
    double top = 0.0;
    for (const BlockDef& b : part.blocks)
    {
        blocks.push_back(objectBounds(ObjectDef(b), catalog));
        top = std::max(top, blocks.back()[1].y);
    }
    std::set<double> lines;
    for (const auto& [lo, hi] : blocks)
    {
        const double y = hi.y;
        const bool floor = hi.x - lo.x >= hi.y - lo.y - kSameEdgeM;
        const bool crossed = std::any_of(blocks.begin(), blocks.end(),
                                         [&](const std::array<Vec2, 2>& b)
                                         { return b[0].y < y - kSameEdgeM && b[1].y > y + kSameEdgeM; });
        if (floor && !crossed && y >= top / 3.0 - kSameEdgeM && y < top - kSameEdgeM)
            lines.insert(y);
    }
    return {lines.begin(), lines.end()};
}

/// The part without the blocks and pigs at or above height.
LevelDef cutAt(const LevelDef& part, double height, const Catalog& catalog)
{
    LevelDef cut = part;
    cut.blocks.clear();
    cut.pigs.clear();
    for (const BlockDef& b : part.blocks)
        if (objectBounds(ObjectDef(b), catalog)[1].y <= height + kSameEdgeM)
            cut.blocks.push_back(b);
    for (const PigDef& p : part.pigs)
        if (objectBounds(ObjectDef(p), catalog)[1].y <= height + kSameEdgeM)
            cut.pigs.push_back(p);
    return cut;
}

/// Builds a level from left to right out of named parts, each varied (stretched, mirrored, iced) as it is placed.
class Builder
{
public:
    Builder(LevelDef& level, const std::vector<GeneratorPart>& parts, const Catalog& catalog, GeneratorRng& rng,
            double start, int maxBodies)
        : m_level(level), m_parts(parts), m_catalog(catalog), m_rng(rng), m_x(start), m_maxBodies(maxBodies)
    {
    }

    /// The part of that name, or null when the folder has none.
    const LevelDef* part(const std::string& name) const
    {
        for (const GeneratorPart& p : m_parts)
            if (p.name == name)
                return &p.shape;
        return nullptr;
    }

    /// Places the part, varied, with its left edge at the builder's x plus gap, on a surface at base; false (and
    /// nothing placed) when the part is missing or would take the level over the body budget.
    bool place(const std::string& name, double gap, double base = 0.0)
    {
        const LevelDef* shape = part(name);
        return shape != nullptr && placeShape(varied(*shape), gap, base);
    }

    /// As place(), the part cut to a height drawn from its storey lines, or whole: one part gives towers of several
    /// heights. What is cut rested on the rest, so the rest stands.
    bool placeCut(const std::string& name, double gap, double base = 0.0, int leave = 0)
    {
        const std::optional<LevelDef> shape = cutVaried(name, leave);
        return shape && placeShape(*shape, gap, base);
    }

    /// The part of that name cut as placeCut() cuts it and varied, or nullopt when the folder has none. The heights
    /// drawn from are those that leave `leave` bodies of the budget for what comes after; when none does, nullopt
    /// (leave > 0) or any height (leave 0: placeShape decides).
    std::optional<LevelDef> cutVaried(const std::string& name, int leave = 0) const
    {
        const LevelDef* shape = part(name);
        if (shape == nullptr)
            return std::nullopt;
        std::vector<LevelDef> cuts;
        for (const double line : storeyLines(*shape, m_catalog))
            cuts.push_back(cutAt(*shape, line, m_catalog));
        cuts.push_back(*shape);
        std::vector<const LevelDef*> fitting;
        for (const LevelDef& cut : cuts)
            if (fits(bodiesOf(cut) + leave))
                fitting.push_back(&cut);
        if (fitting.empty() && leave > 0)
            return std::nullopt;
        if (fitting.empty())
            for (const LevelDef& cut : cuts)
                fitting.push_back(&cut);
        return varied(*fitting[m_rng.index(fitting.size())]);
    }

    /// The shape with a variation drawn for it.
    LevelDef varied(const LevelDef& shape) const
    {
        return varyPart(shape, drawPartVariation(shape, m_rng, m_catalog), m_catalog);
    }

    /// The part of that name with only what lies below height, or null when the folder has none.
    std::optional<LevelDef> partBelow(const std::string& name, double height) const
    {
        const LevelDef* shape = part(name);
        if (shape == nullptr)
            return std::nullopt;
        return cutAt(*shape, height, m_catalog);
    }

    bool placeShape(const LevelDef& shape, double gap, double base = 0.0)
    {
        if (bodiesOf(m_level) + bodiesOf(shape) > m_maxBodies || bodiesOf(shape) == 0)
            return false;
        const PartSpan e = partSpan(shape, m_catalog);
        const double dx = m_x + gap - e.left;
        for (BlockDef b : shape.blocks)
        {
            b.x = tidyMetres(b.x + dx);
            b.y = tidyMetres(b.y + base);
            m_level.blocks.push_back(b);
        }
        for (PigDef p : shape.pigs)
        {
            p.x = tidyMetres(p.x + dx);
            p.y = tidyMetres(p.y + base);
            m_level.pigs.push_back(p);
        }
        m_x = tidyMetres(e.right + dx);
        return true;
    }

    /// Whether `more` bodies still fit in the budget.
    bool fits(int more) const { return bodiesOf(m_level) + more <= m_maxBodies; }

    double x() const { return m_x; }
    const Catalog& catalog() const { return m_catalog; }
    void advance(double dx) { m_x += dx; }
    LevelDef& level() { return m_level; }

private:
    LevelDef& m_level;
    const std::vector<GeneratorPart>& m_parts;
    const Catalog& m_catalog;
    GeneratorRng& m_rng;
    double m_x;
    int m_maxBodies;
};

std::string pick(GeneratorRng& rng, const std::vector<std::string>& names)
{
    return names[rng.index(names.size())];
}

// C++ leaves the order of a call's arguments open: `place(pick(rng, ...), rng.metres(...))` drew the gap first with
// GCC and the name first with clang, so one seed made two layouts. These draw the gap, then the name, always (GCC's
// order, in which the shipped and golden levels were made).
bool placeAny(Builder& b, GeneratorRng& rng, const std::vector<std::string>& names, double lo, double hi)
{
    const double gap = rng.metres(lo, hi);
    return b.place(pick(rng, names), gap);
}

bool placeAnyCut(Builder& b, GeneratorRng& rng, const std::vector<std::string>& names, double lo, double hi)
{
    const double gap = rng.metres(lo, hi);
    return b.placeCut(pick(rng, names), gap);
}

void towers(Builder& b, GeneratorRng& rng)
{
    // Closer than they are tall, so each can fall onto the next; the first has pigs. Each is cut to a height of its
    // own (whole towers of three parts came out alike across seeds).
    const std::size_t count = 3 + rng.index(2); // those over the body budget are left out
    b.placeCut(pick(rng, {"tower-3", "ice-tower-2", "keep-2"}), 0.0);
    for (std::size_t i = 1; i < count; ++i)
        placeAnyCut(b, rng, {"tower-3", "ice-tower-2", "keep-2", "column-4"}, 0.4, 1.9);
}

void castle(Builder& b, GeneratorRng& rng)
{
    // One or two outworks, the keep, and one to three towers behind it, keep and towers each cut to a height of its
    // own: an outwork and a whole keep alone came out alike across seeds (ten of 34 castles in a 200-level run).
    const std::vector<std::string> outworks{"gate",      "cage",         "frame",       "tnt-on-frame",
                                            "pyramid-3", "double-frame", "roofed-frame"};
    b.place(pick(rng, outworks), 0.0);
    if (rng.coin())
        placeAny(b, rng, outworks, 0.6, 2.0);
    // The keep leaves room for a tower (a whole fortress and a cage filled the budget: a few castles, many alike).
    constexpr int kTowerRoom = 4;
    const double keepGap = rng.metres(1.0, 3.0);
    if (!b.placeCut(pick(rng, {"fortress", "castle", "keep-2"}), keepGap, 0.0, kTowerRoom))
        b.placeCut("keep-2", rng.metres(1.0, 3.0), 0.0, kTowerRoom);
    const std::size_t towers = 1 + rng.index(3); // those over the body budget are left out
    for (std::size_t i = 0; i < towers; ++i)
        placeAnyCut(b, rng, {"tower-3", "ice-tower-2", "column-4", "keep-2", "roofed-frame"}, 0.4, 2.0);
}

void cages(Builder& b, GeneratorRng& rng)
{
    const std::size_t count = 3 + rng.index(3);
    for (std::size_t i = 0; i < count; ++i)
    {
        const std::vector<std::string> names{"cage", "frame", "double-frame", "roofed-frame", "gate"};
        if (i == 0)
            b.place(pick(rng, names), 0.0);
        else
            placeAny(b, rng, names, 0.8, 2.5);
    }
}

void pyramid(Builder& b, GeneratorRng& rng)
{
    b.placeCut("pyramid-3", 0.0);
    const double gap = rng.metres(0.8, 2.0);
    if (!b.placeCut(pick(rng, {"frame", "roofed-frame", "double-frame", "cage", "gate"}), gap))
        b.place("frame", gap); // the smallest frame, in a small budget
    if (rng.coin())
        b.placeCut("pyramid-3", rng.metres(0.8, 2.0));
    placeAnyCut(b, rng, {"frame", "roofed-frame", "cage", "tower-3", "ice-tower-2", "double-frame"}, 0.8, 2.0);
    if (rng.coin())
        b.placeCut("pyramid-3", rng.metres(0.8, 2.0));
}

/// A pig of a size drawn from types, resting on a surface at height.
PigDef pigOn(GeneratorRng& rng, const Catalog& catalog, const std::vector<std::string>& types, double x, double height)
{
    const std::string type = pick(rng, types);
    const PigType* pig = catalog.findPig(type);
    return {type, x, tidyMetres(height + (pig != nullptr ? pig->radiusM : 0.25))};
}

void bridge(Builder& b, GeneratorRng& rng)
{
    // Stone columns of two to four blocks and a wood plank across each span, a pig (or a caged pig) on it and a pig
    // beneath; one to three spans, sometimes an outwork before and a frame after (a single span alone repeated across
    // seeds).
    const bool outwork = rng.coin();
    if (outwork)
        b.place(pick(rng, {"frame", "cage", "pyramid-3", "roofed-frame", "gate"}), 0.0);
    const double top = 0.8 * static_cast<double>(2 + rng.index(3)); // column-4's blocks are 0.8 m
    std::optional<LevelDef> column = b.partBelow("column-4", top);
    if (column)
        column = b.varied(*column); // every column alike: the planks span between them
    const std::size_t spans = 1 + rng.index(3);
    if (!column || !b.placeShape(*column, outwork ? rng.metres(1.0, 2.5) : 0.0))
        return;
    const PartSpan columnSpan = partSpan(*column, b.catalog());
    const double columnWidth = columnSpan.right - columnSpan.left;
    std::vector<double> rights{b.x()}; // each column's right edge
    for (std::size_t i = 0; i < spans && b.placeShape(*column, rng.metres(2.6, 4.6)); ++i)
        rights.push_back(b.x());
    LevelDef& level = b.level();
    for (std::size_t j = 0; j + 1 < rights.size() && b.fits(4); ++j)
    {
        // Planks meet over a shared column's middle; the outer ends reach the outer edges.
        const double left = rights[j] - (j == 0 ? columnWidth : 0.5 * columnWidth);
        const double right = rights[j + 1] - (j + 2 == rights.size() ? 0.0 : 0.5 * columnWidth);
        const double middle = tidyMetres(0.5 * (rights[j] + rights[j + 1] - columnWidth));
        level.blocks.push_back({BlockShape::Box, "wood", tidyMetres(0.5 * (left + right)), top + 0.125,
                                tidyMetres(right - left), 0.25, 0.0, 0.1});
        if (rng.coin())
            level.pigs.push_back(pigOn(rng, b.catalog(), {"small", "medium"}, middle, top + 0.25));
        else
        {
            // A cage on the deck, its pig inside on the cage's floor.
            level.blocks.push_back(
                {BlockShape::HollowBox, "wood", middle, tidyMetres(top + 0.25 + 0.6), 1.2, 1.2, 0.0, 0.1});
            level.pigs.push_back({"small", middle, tidyMetres(top + 0.25 + 0.1 + 0.25)});
        }
        level.pigs.push_back(pigOn(rng, b.catalog(), {"small", "medium", "large"}, middle, 0.0));
    }
    if (rng.coin())
        placeAnyCut(b, rng, {"frame", "cage", "roofed-frame", "tower-3", "ice-tower-2"}, 1.0, 2.5);
}

/// A structure on terrain: a hill from the ground, or an island floating above it; one structure or two side by side.
void raised(Builder& b, GeneratorRng& rng, bool island)
{
    const std::vector<std::string> names{"tower-3", "keep-2", "roofed-frame", "double-frame", "gate", "ice-tower-2"};
    std::vector<std::string> on{pick(rng, names)};
    if (rng.coin())
        on.push_back(pick(rng, names));
    const double margin = rng.metres(1.0, 2.0);
    const double between = rng.metres(0.6, 1.6);
    const double height = island ? rng.metres(2.0, 5.0) : rng.metres(1.5, 3.0);
    // Cut and varied before the ground is sized: a stretched structure must not hang over its edge.
    std::vector<LevelDef> shapes;
    for (const std::string& name : on)
        if (std::optional<LevelDef> shape = b.cutVaried(name))
            shapes.push_back(std::move(*shape));
    if (shapes.empty())
        return;
    double width = 2.0 * margin + between * static_cast<double>(shapes.size() - 1);
    for (const LevelDef& shape : shapes)
    {
        const PartSpan e = partSpan(shape, b.catalog());
        width += e.right - e.left;
    }
    const double thickness = island ? 1.0 : height;
    TerrainDef ground;
    ground.x = tidyMetres(b.x() + 0.5 * width);
    ground.y = tidyMetres(height - 0.5 * thickness);
    ground.widthM = tidyMetres(width);
    ground.heightM = thickness;
    b.level().terrain.push_back(ground);
    const double right = b.x() + width;
    for (std::size_t i = 0; i < shapes.size(); ++i)
        if (!b.placeShape(shapes[i], i == 0 ? margin : between, height))
        {
            const PartSpan e = partSpan(shapes[i], b.catalog());
            b.advance(e.right - e.left + (i == 0 ? margin : between)); // over budget: its place stays empty
        }
    b.advance(right - b.x());
    if (rng.coin())
        placeAny(b, rng, {"frame", "cage"}, 1.0, 2.0); // below an island, beside a hill
}

void tntStore(Builder& b, GeneratorRng& rng)
{
    // Neighbours within the crate's blast: the crate second or third of three or four structures.
    const std::size_t count = 3 + rng.index(2);
    const std::size_t crate = 1 + rng.index(2);
    for (std::size_t i = 0; i < count; ++i)
    {
        if (i == crate)
            b.place("tnt-on-frame", rng.metres(0.5, 2.0));
        else if (i == 0)
            b.placeCut(pick(rng, {"frame", "tower-3", "double-frame", "keep-2", "roofed-frame", "ice-tower-2"}), 0.0);
        else
            placeAnyCut(b, rng, {"frame", "cage", "roofed-frame", "ice-tower-2", "double-frame", "gate", "tower-3"},
                        0.5, 2.0);
    }
}

} // namespace

void applyGeneratorWorld(LevelDef& level, const std::string& world)
{
    if (world == "earth")
        return; // the format's defaults: Earth's gravity in still air, as most campaign levels
    const std::optional<WorldTheme> theme = parseWorldTheme(world);
    if (!theme)
        throw std::invalid_argument("unknown world \"" + world + "\" (expected earth, moon, mars, titan or jupiter)");
    for (const GravityPreset& preset : gravityPresets())
    {
        std::string name(preset.name);
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
        if (name != world)
            continue;
        level.environment.gravity = preset.gravity;
        level.environment.airDensity = preset.airDensity;
    }
    level.theme = theme;
}

namespace
{

/// The occupied 0.5 m cells of a level, as (column, row) from its leftmost body. A cell counts when its centre lies
/// inside a body's bounds or within a micrometre of them: edges often fall exactly on a centre (parts are built in
/// quarter metres), and a last-bit difference between two builds must not decide whether such a cell counts.
std::set<std::pair<int, int>> occupancy(const LevelDef& level, const Catalog& catalog)
{
    constexpr double kCell = 0.5;
    const std::vector<std::array<Vec2, 2>> boxes = bodyBoxes(level, catalog);
    double origin = 1e9;
    for (const auto& [lo, hi] : boxes)
        origin = std::min(origin, lo.x);
    std::set<std::pair<int, int>> cells;
    for (const auto& [lo, hi] : boxes)
        for (int c = static_cast<int>(std::floor((lo.x - origin) / kCell));
             (c + 0.5) * kCell + origin <= hi.x + kSameEdgeM; ++c)
            for (int r = static_cast<int>(std::floor(lo.y / kCell)); (r + 0.5) * kCell <= hi.y + kSameEdgeM; ++r)
            {
                const double x = (c + 0.5) * kCell + origin;
                const double y = (r + 0.5) * kCell;
                if (x >= lo.x - kSameEdgeM && x <= hi.x + kSameEdgeM && y >= lo.y - kSameEdgeM &&
                    y <= hi.y + kSameEdgeM)
                    cells.insert({c, r});
            }
    return cells;
}

} // namespace

double layoutDistance(const LevelDef& a, const LevelDef& b, const Catalog& catalog)
{
    const auto ca = occupancy(a, catalog);
    const auto cb = occupancy(b, catalog);
    std::size_t common = 0;
    for (const auto& cell : ca)
        common += cb.count(cell);
    const std::size_t either = ca.size() + cb.size() - common;
    return either == 0 ? 0.0 : 1.0 - static_cast<double>(common) / static_cast<double>(either);
}

GeneratedKind layOut(LevelDef& level, const std::vector<GeneratorPart>& parts, GeneratorRng& rng,
                     const Catalog& catalog, std::optional<GeneratedKind> only, int maxBodies)
{
    const GeneratedKind drawn = generatedKinds()[rng.index(generatedKinds().size())];
    const GeneratedKind kind = only.value_or(drawn);
    const double start = rng.metres(20.0, 30.0);
    Builder b(level, parts, catalog, rng, start, maxBodies);
    switch (kind)
    {
    case GeneratedKind::Towers:
        towers(b, rng);
        break;
    case GeneratedKind::Castle:
        castle(b, rng);
        break;
    case GeneratedKind::Cages:
        cages(b, rng);
        break;
    case GeneratedKind::Pyramid:
        pyramid(b, rng);
        break;
    case GeneratedKind::Bridge:
        bridge(b, rng);
        break;
    case GeneratedKind::Hill:
        raised(b, rng, false);
        break;
    case GeneratedKind::Island:
        raised(b, rng, true);
        break;
    case GeneratedKind::TntStore:
        tntStore(b, rng);
        break;
    }
    // Every level has a pig and enough to knock down: small layouts get neighbours on the ground beyond.
    while (bodiesOf(level) < std::min(kMinBodies, maxBodies))
        if (!placeAny(b, rng, {"frame", "cage", "pyramid-3", "double-frame"}, 1.0, 2.5))
            break;
    if (level.pigs.empty() && !b.place("frame", rng.metres(1.0, 2.0)))
        throw std::invalid_argument("no castle part with a pig fits in " + std::to_string(maxBodies) +
                                    " bodies (or levels/parts/frame.json is missing)");
    return kind;
}

} // namespace abalike

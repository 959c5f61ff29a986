// The editing model's group edits: align, distribute, a field across a multi-selection, copy, paste and prefabs.
#include "edit/EditCommand.hpp"
#include "edit/EditHelpers.hpp"
#include "edit/History.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelWriter.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace abalike
{

namespace
{

/// The selection without the slingshot, which groups never move.
std::vector<ObjectRef> bodiesOf(const std::vector<ObjectRef>& selection)
{
    std::vector<ObjectRef> refs;
    for (const ObjectRef& ref : selection)
        if (ref.kind != ObjectKind::Slingshot)
            refs.push_back(ref);
    return refs;
}

ObjectDef shifted(const ObjectDef& def, double dx, double dy)
{
    const auto c = centreOf(def);
    return withCentre(def, clampCoordinate(c.x + dx), clampCoordinate(c.y + dy));
}

} // namespace

std::string SceneEditor::changeObjects(const std::vector<ObjectRef>& refs, const std::vector<ObjectDef>& defs,
                                       const std::string& label, const std::string& mergeKey)
{
    if (refs.size() != defs.size())
        return "one definition per object";
    std::vector<ObjectDef> before;
    for (std::size_t i = 0; i < refs.size(); ++i)
    {
        if (!exists(m_level, refs[i]) || kindOf(defs[i]) != refs[i].kind)
            return "no such object";
        if (std::string why = validateObject(defs[i]); !why.empty())
            return describe(m_level, refs[i]) + ": " + why;
        before.push_back(objectDef(m_level, refs[i]));
    }
    if (before == defs)
        return {};
    if (mergeKey.empty())
        m_history->seal();
    push(makeChangeObjects(label, refs, std::move(before), defs, mergeKey));
    if (mergeKey.empty())
        m_history->seal();
    return {};
}

void SceneEditor::alignSelection(Align align)
{
    const std::vector<ObjectRef> refs = bodiesOf(m_selection);
    if (refs.size() < 2)
        return;
    const Catalog catalog = levelCatalog(m_level, m_catalog);
    std::vector<std::array<Vec2, 2>> bounds;
    double left = std::numeric_limits<double>::infinity(), bottom = left;
    double right = -left, top = -left;
    for (const ObjectRef& ref : refs)
    {
        bounds.push_back(objectBounds(objectDef(m_level, ref), catalog));
        left = std::min(left, bounds.back()[0].x);
        bottom = std::min(bottom, bounds.back()[0].y);
        right = std::max(right, bounds.back()[1].x);
        top = std::max(top, bounds.back()[1].y);
    }
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    for (std::size_t i = 0; i < refs.size(); ++i)
    {
        const auto& [lo, hi] = bounds[i];
        double dx = 0.0;
        double dy = 0.0;
        switch (align)
        {
        case Align::Left:
            dx = left - lo.x;
            break;
        case Align::Right:
            dx = right - hi.x;
            break;
        case Align::CentreX:
            dx = 0.5 * (left + right) - 0.5 * (lo.x + hi.x);
            break;
        case Align::Bottom:
            dy = bottom - lo.y;
            break;
        case Align::Top:
            dy = top - hi.y;
            break;
        case Align::CentreY:
            dy = 0.5 * (bottom + top) - 0.5 * (lo.y + hi.y);
            break;
        }
        before.push_back(objectDef(m_level, refs[i]));
        after.push_back(shifted(before.back(), dx, dy));
    }
    m_history->seal();
    push(makeChangeObjects(labelFor("Align", refs.size()), refs, std::move(before), std::move(after), {}));
    m_history->seal();
}

void SceneEditor::distributeSelection(bool horizontal)
{
    const std::vector<ObjectRef> selection = m_selection;
    const std::vector<ObjectRef> refs = bodiesOf(selection);
    if (refs.size() < 3)
        return;
    const Catalog catalog = levelCatalog(m_level, m_catalog);
    const int axis = horizontal ? 0 : 1;
    struct Item
    {
        ObjectRef ref;
        double lo;
        double hi;
    };
    std::vector<Item> items;
    for (const ObjectRef& ref : refs)
    {
        const auto [lo, hi] = objectBounds(objectDef(m_level, ref), catalog);
        items.push_back({ref, coordinate(lo, axis), coordinate(hi, axis)});
    }
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.lo + a.hi < b.lo + b.hi; });
    double sizes = 0.0;
    for (const Item& item : items)
        sizes += item.hi - item.lo;
    const double gap = (items.back().hi - items.front().lo - sizes) / static_cast<double>(items.size() - 1);
    std::vector<ObjectRef> moved;
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    double next = items.front().hi + gap;
    for (std::size_t i = 1; i + 1 < items.size(); ++i)
    {
        const double shift = next - items[i].lo;
        next += items[i].hi - items[i].lo + gap;
        moved.push_back(items[i].ref);
        before.push_back(objectDef(m_level, items[i].ref));
        after.push_back(horizontal ? shifted(before.back(), shift, 0.0) : shifted(before.back(), 0.0, shift));
    }
    m_history->seal();
    push(makeChangeObjects(labelFor("Distribute", refs.size()), moved, std::move(before), std::move(after), {}));
    // The whole selection stays selected, not only the objects that moved.
    applySelection(selection);
    m_history->seal();
}

std::string SceneEditor::copySelection() const
{
    LevelDef scene = emptyScene();
    scene.id = "clipboard";
    scene.title = "Copied from " + (m_level.title.empty() ? std::string("a scene") : m_level.title);
    for (const ObjectRef& ref : bodiesOf(m_selection))
    {
        const ObjectDef def = objectDef(m_level, ref);
        if (const auto* block = std::get_if<BlockDef>(&def))
            scene.blocks.push_back(*block);
        else if (const auto* pig = std::get_if<PigDef>(&def))
            scene.pigs.push_back(*pig);
        else if (const auto* terrain = std::get_if<TerrainDef>(&def))
            scene.terrain.push_back(*terrain);
    }
    if (scene.blocks.empty() && scene.pigs.empty() && scene.terrain.empty())
        return {};
    return writeLevelJson(scene, "");
}

std::vector<ObjectDef> SceneEditor::placedBodies(const LevelDef& source, const std::optional<Vec2>& at) const
{
    std::vector<ObjectDef> bodies;
    for (const TerrainDef& terrain : source.terrain)
        bodies.emplace_back(terrain);
    for (const BlockDef& block : source.blocks)
        bodies.emplace_back(block);
    for (const PigDef& pig : source.pigs)
        bodies.emplace_back(pig);
    if (bodies.empty() || !at)
        return bodies;
    const Catalog catalog = levelCatalog(m_level, m_catalog);
    double left = std::numeric_limits<double>::infinity(), bottom = left, right = -left;
    for (const ObjectDef& def : bodies)
    {
        const auto [lo, hi] = objectBounds(def, catalog);
        left = std::min(left, lo.x);
        right = std::max(right, hi.x);
        bottom = std::min(bottom, lo.y);
    }
    double dx = (*at).x - 0.5 * (left + right);
    double dy = std::max((*at).y, m_level.groundY) - bottom;
    // On the grid: the group moves by whole grid steps, so bodies that were on it stay on it.
    if (m_snap.grid && m_snap.gridM > 0.0)
    {
        dx = std::round(dx / m_snap.gridM) * m_snap.gridM;
        dy = std::max(m_level.groundY - bottom, std::round(dy / m_snap.gridM) * m_snap.gridM);
    }
    for (ObjectDef& def : bodies)
        def = shifted(def, dx, dy);
    // The group's lowest bodies settle onto what is under them, from any height (a paste above a tower lands on it);
    // the rest keep formation.
    if (m_snap.surfaces)
    {
        SnapSettings settle = m_snap;
        settle.grid = false;
        settle.surfaceReachM = 2.0 * limits::kWorldExtentM;
        double lift = -std::numeric_limits<double>::infinity();
        for (const ObjectDef& def : bodies)
        {
            if (kindOf(def) == ObjectKind::Terrain || objectBounds(def, catalog)[0].y > bottom + dy + 1e-6)
                continue;
            const SnapResult snapped = snapObject(m_level, catalog, def, {}, settle);
            if (snapped.onGround || snapped.restsOn)
                lift = std::max(lift, snapped.y - centreOf(def).y);
        }
        if (std::isfinite(lift))
            for (ObjectDef& def : bodies)
                def = shifted(def, 0.0, lift);
    }
    return bodies;
}

std::string SceneEditor::insertBodies(const LevelDef& source, const std::optional<Vec2>& at, const std::string& label)
{
    std::vector<ObjectDef> bodies = placedBodies(source, at);
    if (bodies.empty())
        return "it holds no blocks, pigs or terrain";
    LevelDef combined = m_level;
    for (const ObjectDef& def : bodies)
    {
        if (const auto* block = std::get_if<BlockDef>(&def))
            combined.blocks.push_back(*block);
        else if (const auto* pig = std::get_if<PigDef>(&def))
            combined.pigs.push_back(*pig);
        else if (const auto* terrain = std::get_if<TerrainDef>(&def))
            combined.terrain.push_back(*terrain);
    }
    if (const auto issues = checkLevelFields(combined, m_catalog); !issues.empty())
        return issues.front().message;
    m_history->seal();
    push(makeAddObjects(label, m_level, std::move(bodies)));
    m_history->seal();
    return {};
}

std::string SceneEditor::paste(std::string_view text, const std::optional<Vec2>& at)
{
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        return "the clipboard is empty";
    LevelDef source;
    try
    {
        source = parseLevelForEditing(text, "clipboard", m_catalog).level;
    }
    catch (const LevelLoadError& e)
    {
        return "the clipboard holds no level JSON (" +
               (e.issues().empty() ? std::string("unreadable") : e.issues().front().message) + ")";
    }
    const std::size_t count = source.blocks.size() + source.pigs.size() + source.terrain.size();
    return insertBodies(source, at, labelFor("Paste", count));
}

// ---------------------------------------------------------------- terrain polygon corners

std::string SceneEditor::moveVertex(std::size_t terrain, std::size_t vertex, double x, double y,
                                    const std::string& mergeKey)
{
    if (terrain >= m_level.terrain.size() || vertex >= m_level.terrain[terrain].points.size())
        return "no such corner";
    TerrainDef def = m_level.terrain[terrain];
    def.points[vertex] = {clampCoordinate(x), clampCoordinate(y)};
    fitPolygonBounds(def);
    return changeObject({ObjectKind::Terrain, terrain}, def, "Move a corner", mergeKey);
}

std::string SceneEditor::insertVertex(std::size_t terrain, std::size_t vertex)
{
    if (terrain >= m_level.terrain.size() || vertex >= m_level.terrain[terrain].points.size())
        return "no such corner";
    TerrainDef def = m_level.terrain[terrain];
    const auto& a = def.points[vertex];
    const auto& b = def.points[(vertex + 1) % def.points.size()];
    const Vec2 middle{clampCoordinate(0.5 * (a.x + b.x)), clampCoordinate(0.5 * (a.y + b.y))};
    def.points.insert(def.points.begin() + static_cast<std::ptrdiff_t>(vertex + 1), middle);
    fitPolygonBounds(def);
    return changeObject({ObjectKind::Terrain, terrain}, def, "Add a corner");
}

std::string SceneEditor::removeVertex(std::size_t terrain, std::size_t vertex)
{
    if (terrain >= m_level.terrain.size() || vertex >= m_level.terrain[terrain].points.size())
        return "no such corner";
    TerrainDef def = m_level.terrain[terrain];
    if (def.points.size() <= 3)
        return "a polygon keeps at least 3 corners";
    def.points.erase(def.points.begin() + static_cast<std::ptrdiff_t>(vertex));
    fitPolygonBounds(def);
    return changeObject({ObjectKind::Terrain, terrain}, def, "Remove a corner");
}

} // namespace abalike

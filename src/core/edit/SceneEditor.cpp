#include "edit/ConvexShape.hpp"
#include "edit/EditCommand.hpp"
#include "edit/EditHelpers.hpp"
#include "edit/History.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/util/Angles.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

namespace abalike
{

namespace
{

/// Half the width of the slingshot's frame and how far above the pouch it reaches, for picking it (m).
constexpr double kSlingshotPickHalfWidthM = 0.4;
constexpr double kSlingshotPickAboveM = 0.4;

/// Every object of the level, in drawing order from the back: terrain, the slingshot, blocks, pigs.
std::vector<ObjectRef> allObjects(const LevelDef& level)
{
    std::vector<ObjectRef> out;
    for (std::size_t i = 0; i < level.terrain.size(); ++i)
        out.push_back({ObjectKind::Terrain, i});
    out.push_back({ObjectKind::Slingshot, 0});
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
        out.push_back({ObjectKind::Block, i});
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
        out.push_back({ObjectKind::Pig, i});
    return out;
}

/// A level of properties only, with the one object in it, for checking that object's values.
LevelDef levelWithOnly(const LevelDef& level, const ObjectDef& def)
{
    LevelDef out = level;
    out.blocks.clear();
    out.pigs.clear();
    out.terrain.clear();
    out.sandbox = true; // no pig needed
    if (const auto* block = std::get_if<BlockDef>(&def))
        out.blocks.push_back(*block);
    else if (const auto* pig = std::get_if<PigDef>(&def))
        out.pigs.push_back(*pig);
    else if (const auto* terrain = std::get_if<TerrainDef>(&def))
        out.terrain.push_back(*terrain);
    else
        out.slingshot = std::get<SlingshotDef>(def);
    return out;
}

} // namespace

std::string schemaReferenceToWrite(const std::filesystem::path& path, const std::filesystem::path& schemaPath)
{
    // A file that has a "$schema" keeps it as written: it may point at a copy only its author has.
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec))
    {
        std::ifstream in(path, std::ios::binary);
        const nlohmann::json root = nlohmann::json::parse(in, nullptr, false);
        if (root.is_object())
            return root.contains("$schema") && root["$schema"].is_string() ? root["$schema"].get<std::string>()
                                                                           : std::string();
    }
    // A new file gets the schema's path only when the schema sits beside it: "level.schema.json",
    // "schema/level.schema.json" or the same one folder up ("../schema/level.schema.json", as in levels/). A path
    // into another tree (where the program is installed, "../abalike-play/share/...") breaks when the file is shared.
    if (schemaPath.empty())
        return {};
    const std::string relative = schemaReferenceFor(path, schemaPath);
    std::vector<std::string> parts;
    for (const auto& part : std::filesystem::path(relative).lexically_normal())
        parts.push_back(part.string());
    const std::size_t up = !parts.empty() && parts.front() == ".." ? 1 : 0;
    const bool beside = !relative.empty() && relative.front() != '/' && parts.size() >= up + 1 &&
                        parts.size() <= up + 2 && std::count(parts.begin(), parts.end(), "..") == static_cast<long>(up);
    return beside ? relative : std::string();
}

LevelDef emptyScene()
{
    LevelDef level;
    level.id = "sandbox";
    level.title = "Sandbox";
    level.sandbox = true;
    level.slingshot.x = 0.0; // the default band (1800 N at 2 m)
    level.slingshot.y = 1.5;
    level.birds = {"red", "red", "red"};
    return level;
}

SceneEditor::SceneEditor(LevelDef level, const Catalog& catalog)
    : m_level(std::move(level)), m_catalog(catalog), m_history(std::make_unique<History>())
{
    m_savedState = m_history->state();
}

SceneEditor::~SceneEditor() = default;

// ---------------------------------------------------------------- selection

bool SceneEditor::isSelected(const ObjectRef& ref) const
{
    return std::binary_search(m_selection.begin(), m_selection.end(), ref);
}

void SceneEditor::applySelection(std::vector<ObjectRef> refs)
{
    refs.erase(std::remove_if(refs.begin(), refs.end(), [this](const ObjectRef& r) { return !exists(m_level, r); }),
               refs.end());
    std::sort(refs.begin(), refs.end());
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    m_selection = std::move(refs);
}

void SceneEditor::select(const ObjectRef& ref, SelectMode mode)
{
    if (!exists(m_level, ref))
        return;
    std::vector<ObjectRef> next = mode == SelectMode::Replace ? std::vector<ObjectRef>{} : m_selection;
    const auto it = std::find(next.begin(), next.end(), ref);
    if (mode == SelectMode::Toggle && it != next.end())
        next.erase(it);
    else
        next.push_back(ref);
    applySelection(std::move(next));
}

void SceneEditor::selectInRect(double x0, double y0, double x1, double y1, SelectMode mode)
{
    const double left = std::min(x0, x1);
    const double right = std::max(x0, x1);
    const double bottom = std::min(y0, y1);
    const double top = std::max(y0, y1);
    std::vector<ObjectRef> inside;
    for (const ObjectRef& ref : allObjects(m_level))
    {
        const auto [lo, hi] = objectBounds(objectDef(m_level, ref), m_catalog);
        if (lo.x >= left && hi.x <= right && lo.y >= bottom && hi.y <= top)
            inside.push_back(ref);
    }
    if (mode == SelectMode::Replace)
    {
        applySelection(std::move(inside));
        return;
    }
    for (const ObjectRef& ref : inside)
        select(ref, mode);
}

void SceneEditor::selectAll()
{
    applySelection(allObjects(m_level));
}

void SceneEditor::clearSelection()
{
    m_selection.clear();
}

std::vector<Vec2> SceneEditor::outline(const ObjectRef& ref) const
{
    if (!exists(m_level, ref))
        return {};
    return outlineOf(objectDef(m_level, ref));
}

std::vector<Vec2> SceneEditor::outlineOf(const ObjectDef& def) const
{
    if (const auto* s = std::get_if<SlingshotDef>(&def))
    {
        const double bottom = std::min(m_level.groundY, s->y - kSlingshotPickAboveM);
        const double top = s->y + kSlingshotPickAboveM;
        return {{s->x - kSlingshotPickHalfWidthM, bottom},
                {s->x + kSlingshotPickHalfWidthM, bottom},
                {s->x + kSlingshotPickHalfWidthM, top},
                {s->x - kSlingshotPickHalfWidthM, top}};
    }
    // A terrain polygon is drawn as its own corners, not the convex hull that picks and snaps it.
    if (const auto* t = std::get_if<TerrainDef>(&def); t != nullptr && t->isPolygon())
        return t->points;
    return objectShape(def, levelCatalog(m_level, m_catalog));
}

std::optional<ObjectRef> SceneEditor::objectAt(double x, double y) const
{
    const std::vector<ObjectRef> objects = allObjects(m_level);
    for (auto it = objects.rbegin(); it != objects.rend(); ++it)
    {
        if (it->kind == ObjectKind::Slingshot)
        {
            const SlingshotDef& s = m_level.slingshot;
            if (std::abs(x - s.x) <= kSlingshotPickHalfWidthM && y <= s.y + kSlingshotPickAboveM &&
                y >= std::min(m_level.groundY, s.y - kSlingshotPickAboveM))
                return *it;
            continue;
        }
        if (it->kind == ObjectKind::Terrain && m_level.terrain[it->index].isPolygon())
        {
            // A polygon by its own outline: a click in a hill's dip is on what is behind it, not on the hill.
            if (polygonContains(m_level.terrain[it->index].points, x, y))
                return *it;
            continue;
        }
        if (shapeContains(objectShape(objectDef(m_level, *it), m_catalog), {x, y}))
            return *it;
    }
    return std::nullopt;
}

// ---------------------------------------------------------------- edits

void SceneEditor::push(std::unique_ptr<EditCommand> command)
{
    const auto after = command->selectionAfter();
    m_history->push(std::move(command), m_level);
    ++m_revision;
    if (after)
        applySelection(*after);
}

std::string SceneEditor::validateObject(const ObjectDef& def) const
{
    const auto issues = checkLevelFields(levelWithOnly(m_level, def), m_catalog);
    if (issues.empty())
        return {};
    // "/blocks/0/w: ..." -> "w: ...": the object is the one being edited.
    const LevelIssue& first = issues.front();
    std::string where = first.pointer;
    if (const auto object = objectOfPointer(where))
        where = where.substr(std::min(where.size(), pointerOf(*object).size() + 1));
    return (where.empty() ? "" : where + ": ") + first.message;
}

SnapResult SceneEditor::snap(const ObjectDef& def, const std::vector<ObjectRef>& ignore) const
{
    return snapObject(m_level, levelCatalog(m_level, m_catalog), def, ignore, m_snap);
}

ObjectRef SceneEditor::place(const ObjectDef& def)
{
    const SnapResult at = snap(def);
    const ObjectDef placed = withCentre(def, clampCoordinate(at.x), clampCoordinate(at.y));
    if (const std::string why = validateObject(placed); !why.empty())
        throw std::invalid_argument("cannot place it: " + why);
    m_history->seal();
    if (kindOf(placed) == ObjectKind::Slingshot)
    {
        const ObjectRef ref{ObjectKind::Slingshot, 0};
        push(makeChangeObjects("Move the slingshot", {ref}, {objectDef(m_level, ref)}, {placed}, {}));
        m_history->seal();
        return ref;
    }
    const char* what = kindOf(placed) == ObjectKind::Block ? "Place a block"
                       : kindOf(placed) == ObjectKind::Pig ? "Place a pig"
                                                           : "Place terrain";
    push(makeAddObjects(what, m_level, {placed}));
    m_history->seal();
    return m_selection.front();
}

void SceneEditor::moveSelection(double dx, double dy)
{
    const std::vector<ObjectRef> refs = m_selection;
    if (refs.empty())
        return;
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    for (const ObjectRef& ref : refs)
    {
        before.push_back(objectDef(m_level, ref));
        const auto c = centreOf(before.back());
        after.push_back(withCentre(before.back(), clampCoordinate(c.x + dx), clampCoordinate(c.y + dy)));
    }
    push(makeChangeObjects(labelFor("Move", refs.size()), refs, std::move(before), std::move(after), "move"));
}

void SceneEditor::beginDrag(const ObjectRef& grabbed)
{
    if (!exists(m_level, grabbed))
        return;
    if (!isSelected(grabbed))
        select(grabbed);
    m_history->seal();
    Drag drag;
    drag.grabbed = grabbed;
    drag.refs = m_selection;
    for (const ObjectRef& ref : drag.refs)
        drag.start.push_back(objectDef(m_level, ref));
    m_drag = std::move(drag);
}

void SceneEditor::dragTo(double dx, double dy)
{
    if (!m_drag)
        return;
    const Drag& drag = *m_drag;
    const std::size_t grabbed =
        static_cast<std::size_t>(std::find(drag.refs.begin(), drag.refs.end(), drag.grabbed) - drag.refs.begin());
    // Snap the grabbed object; the rest of the selection keeps its place relative to it.
    const auto c = centreOf(drag.start[grabbed]);
    const SnapResult at = snap(withCentre(drag.start[grabbed], c.x + dx, c.y + dy), drag.refs);
    const double sx = at.x - c.x;
    const double sy = at.y - c.y;
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    for (std::size_t i = 0; i < drag.refs.size(); ++i)
    {
        before.push_back(objectDef(m_level, drag.refs[i]));
        const auto p = centreOf(drag.start[i]);
        after.push_back(withCentre(drag.start[i], clampCoordinate(p.x + sx), clampCoordinate(p.y + sy)));
    }
    if (before == after)
        return;
    push(makeChangeObjects(labelFor("Move", drag.refs.size()), drag.refs, std::move(before), std::move(after), "drag"));
}

void SceneEditor::endDrag()
{
    m_drag.reset();
    m_history->seal();
}

void SceneEditor::rotateSelection(double deltaDeg)
{
    const std::vector<ObjectRef> refs = m_selection;
    if (refs.empty() || deltaDeg == 0.0)
        return;
    double px = 0.0;
    double py = 0.0;
    for (const ObjectRef& ref : refs)
    {
        const auto c = centreOf(objectDef(m_level, ref));
        px += c.x / static_cast<double>(refs.size());
        py += c.y / static_cast<double>(refs.size());
    }
    const double c = std::cos(deltaDeg * kDegToRad);
    const double s = std::sin(deltaDeg * kDegToRad);
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    for (const ObjectRef& ref : refs)
    {
        before.push_back(objectDef(m_level, ref));
        const auto p = centreOf(before.back());
        ObjectDef turned = before.back();
        if (refs.size() > 1)
            turned = withCentre(turned, clampCoordinate(px + c * (p.x - px) - s * (p.y - py)),
                                clampCoordinate(py + s * (p.x - px) + c * (p.y - py)));
        if (auto* block = std::get_if<BlockDef>(&turned))
            block->angleDeg = normaliseAngle(block->angleDeg + deltaDeg);
        else if (auto* terrain = std::get_if<TerrainDef>(&turned); terrain != nullptr && terrain->isPolygon())
            rotatePolygon(*terrain, deltaDeg);
        else if (auto* terrain = std::get_if<TerrainDef>(&turned))
            terrain->angleDeg = normaliseAngle(terrain->angleDeg + deltaDeg);
        after.push_back(std::move(turned));
    }
    push(makeChangeObjects(labelFor("Rotate", refs.size()), refs, std::move(before), std::move(after), "rotate"));
}

std::string SceneEditor::resizeObject(const ObjectRef& ref, double widthM, double heightM, const std::string& mergeKey)
{
    if (!exists(m_level, ref))
        return "no such object";
    ObjectDef def = objectDef(m_level, ref);
    const auto grow = [](double& x, double& y, double angleDeg, double oldH, double newH)
    {
        // Keep the bottom edge where it is: the centre moves up (along the object's own up) by half the growth.
        const double a = angleDeg * kDegToRad;
        x = cleanMetres(x - std::sin(a) * (newH - oldH) / 2.0);
        y = cleanMetres(y + std::cos(a) * (newH - oldH) / 2.0);
    };
    widthM = cleanMetres(widthM);
    heightM = cleanMetres(heightM);
    if (auto* block = std::get_if<BlockDef>(&def))
    {
        if (block->shape == BlockShape::Circle)
            heightM = widthM;
        grow(block->x, block->y, block->angleDeg, block->heightM, heightM);
        block->widthM = widthM;
        block->heightM = heightM;
    }
    else if (auto* terrain = std::get_if<TerrainDef>(&def); terrain != nullptr && terrain->isPolygon())
        return "a terrain polygon's size is its points: move them in its file";
    else if (auto* terrain = std::get_if<TerrainDef>(&def))
    {
        grow(terrain->x, terrain->y, terrain->angleDeg, terrain->heightM, heightM);
        terrain->widthM = widthM;
        terrain->heightM = heightM;
    }
    else
        return "only blocks and terrain have a size";
    return changeObject(ref, def, "Resize " + describe(m_level, ref), mergeKey);
}

void SceneEditor::mirrorSelection()
{
    const std::vector<ObjectRef> refs = m_selection;
    if (refs.empty())
        return;
    double left = 1e300;
    double right = -1e300;
    for (const ObjectRef& ref : refs)
    {
        const auto bounds = shapeBounds(objectShape(objectDef(m_level, ref), m_catalog));
        left = std::min(left, bounds[0].x);
        right = std::max(right, bounds[1].x);
    }
    const double axis = 0.5 * (left + right);
    std::vector<ObjectDef> before;
    std::vector<ObjectDef> after;
    for (const ObjectRef& ref : refs)
    {
        before.push_back(objectDef(m_level, ref));
        ObjectDef mirrored = before.back();
        const auto centre = centreOf(mirrored);
        mirrored = withCentre(mirrored, clampCoordinate(cleanMetres(2.0 * axis - centre.x)), centre.y);
        if (auto* block = std::get_if<BlockDef>(&mirrored))
        {
            if (block->shape == BlockShape::Triangle)
            {
                // The right angle at the bottom left, mirrored, is at the bottom right: the same triangle with its
                // legs swapped, turned a quarter.
                std::swap(block->widthM, block->heightM);
                block->angleDeg = normaliseAngle(90.0 - block->angleDeg);
            }
            else
                block->angleDeg = normaliseAngle(-block->angleDeg);
        }
        else if (auto* terrain = std::get_if<TerrainDef>(&mirrored))
        {
            if (terrain->isPolygon())
                for (auto& point : terrain->points)
                    point.x = cleanMetres(2.0 * terrain->x - point.x);
            else
                terrain->angleDeg = normaliseAngle(-terrain->angleDeg);
        }
        after.push_back(std::move(mirrored));
    }
    push(makeChangeObjects(labelFor("Mirror", refs.size()), refs, std::move(before), std::move(after), "mirror"));
}

void SceneEditor::duplicateSelection()
{
    std::vector<ObjectDef> copies;
    double left = std::numeric_limits<double>::infinity();
    double right = -left;
    const Catalog catalog = levelCatalog(m_level, m_catalog);
    for (const ObjectRef& ref : m_selection)
    {
        if (ref.kind == ObjectKind::Slingshot)
            continue;
        copies.push_back(objectDef(m_level, ref));
        const auto [lo, hi] = objectBounds(copies.back(), catalog);
        left = std::min(left, lo.x);
        right = std::max(right, hi.x);
    }
    if (copies.empty())
        return;
    // Beside the originals, touching them: duplicating a tower builds the next one. On the grid when it is on.
    double dx = right - left;
    if (m_snap.grid && m_snap.gridM > 0.0)
        dx = std::ceil(dx / m_snap.gridM - 1e-9) * m_snap.gridM;
    for (ObjectDef& copy : copies)
    {
        const auto c = centreOf(copy);
        copy = withCentre(copy, clampCoordinate(c.x + dx), c.y);
    }
    m_history->seal();
    push(makeAddObjects(labelFor("Duplicate", copies.size()), m_level, std::move(copies)));
    m_history->seal();
}

void SceneEditor::deleteSelection()
{
    std::vector<ObjectRef> refs;
    for (const ObjectRef& ref : m_selection)
        if (ref.kind != ObjectKind::Slingshot)
            refs.push_back(ref);
    if (refs.empty())
        return;
    m_drag.reset();
    m_history->seal();
    const std::size_t count = refs.size();
    push(makeRemoveObjects(labelFor("Delete", count), m_level, std::move(refs)));
    m_history->seal();
}

std::string SceneEditor::changeObject(const ObjectRef& ref, const ObjectDef& def, const std::string& label,
                                      const std::string& mergeKey)
{
    if (!exists(m_level, ref) || kindOf(def) != ref.kind)
        return "no such object";
    if (std::string why = validateObject(def); !why.empty())
        return why;
    const ObjectDef before = objectDef(m_level, ref);
    if (before == def)
        return {};
    if (mergeKey.empty())
        m_history->seal();
    push(makeChangeObjects(label, {ref}, {before}, {def}, mergeKey));
    if (mergeKey.empty())
        m_history->seal();
    return {};
}

std::string SceneEditor::setProperties(const LevelDef& properties, const std::string& label,
                                       const std::string& mergeKey)
{
    LevelDef check = properties;
    check.blocks.clear();
    check.pigs.clear();
    check.terrain.clear();
    check.sandbox = true; // the pigs are not a property; saveProblems() reports a level without any
    if (const auto issues = checkLevelFields(check, m_catalog); !issues.empty())
        return issues.front().pointer + ": " + issues.front().message;
    if (mergeKey.empty())
        m_history->seal();
    push(makeSetProperties(label, m_level, properties, mergeKey));
    if (mergeKey.empty())
        m_history->seal();
    return {};
}

// ---------------------------------------------------------------- history

bool SceneEditor::undo()
{
    m_drag.reset();
    const EditCommand* command = m_history->undo(m_level);
    if (command == nullptr)
        return false;
    ++m_revision;
    if (const auto before = command->selectionBefore())
        applySelection(*before);
    else
        applySelection(m_selection); // drops what no longer exists
    return true;
}

bool SceneEditor::redo()
{
    m_drag.reset();
    const EditCommand* command = m_history->redo(m_level);
    if (command == nullptr)
        return false;
    ++m_revision;
    if (const auto after = command->selectionAfter())
        applySelection(*after);
    else
        applySelection(m_selection);
    return true;
}

bool SceneEditor::canUndo() const
{
    return m_history->canUndo();
}

bool SceneEditor::canRedo() const
{
    return m_history->canRedo();
}

std::string SceneEditor::undoLabel() const
{
    return m_history->undoLabel();
}

std::string SceneEditor::redoLabel() const
{
    return m_history->redoLabel();
}

void SceneEditor::endGesture()
{
    m_history->seal();
}

// ---------------------------------------------------------------- file

bool SceneEditor::dirty() const
{
    return m_history->state() != m_savedState;
}

void SceneEditor::markSaved()
{
    m_savedState = m_history->state();
}

void SceneEditor::markUnsaved()
{
    m_savedState = ~m_history->state(); // differs from every state until a save
}

std::vector<LevelIssue> SceneEditor::saveProblems() const
{
    return checkLevelFields(m_level, m_catalog);
}

std::vector<LevelIssue> SceneEditor::save(const std::filesystem::path& path, const std::filesystem::path& schemaPath)
{
    if (auto problems = saveProblems(); !problems.empty())
    {
        for (LevelIssue& issue : problems)
            issue.file = path.string();
        throw LevelLoadError(std::move(problems));
    }
    const std::string text = writeLevelJson(m_level, schemaReferenceToWrite(path, schemaPath));
    // Read it back before writing: a file the editor writes always opens again.
    EditableLevel reread = parseLevelForEditing(text, path.string(), m_catalog);
    writeFileAtomically(path, text);
    m_path = path;
    m_level.sourcePath = path.string();
    markSaved();
    for (LevelIssue& issue : reread.geometryIssues)
        issue.line = issue.column = 0;
    return reread.geometryIssues;
}

} // namespace abalike

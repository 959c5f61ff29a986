#pragma once

#include <abalike/edit/SceneObject.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// One undoable edit of a level. apply() takes the level from the state before to the state after, revert() back;
/// both leave it exactly (bit for bit) as it was, so any sequence of undo and redo ends in a state seen before.
class EditCommand
{
public:
    virtual ~EditCommand() = default;
    virtual void apply(LevelDef& level) const = 0;
    virtual void revert(LevelDef& level) const = 0;
    /// What the edit did, for the Undo and Redo menu items: "Move 3 objects".
    virtual std::string label() const = 0;
    /// The objects to select once the edit is applied, and once it is reverted; none: the selection stays.
    virtual std::optional<std::vector<ObjectRef>> selectionAfter() const { return std::nullopt; }
    virtual std::optional<std::vector<ObjectRef>> selectionBefore() const { return std::nullopt; }
    /// Folds a later edit into this one (successive steps of one drag or slider); false if the two cannot merge.
    virtual bool merge(const EditCommand&) { return false; }
};

/// Objects changed in place: moved, turned, resized, or given other properties. Merges with a later change of the
/// same objects under the same merge key.
std::unique_ptr<EditCommand> makeChangeObjects(std::string label, std::vector<ObjectRef> refs,
                                               std::vector<ObjectDef> before, std::vector<ObjectDef> after,
                                               std::string mergeKey);

/// Objects added to the end of their lists (placed, duplicated, pasted).
std::unique_ptr<EditCommand> makeAddObjects(std::string label, const LevelDef& level, std::vector<ObjectDef> objects);

/// Objects removed from their lists (the slingshot cannot be removed).
std::unique_ptr<EditCommand> makeRemoveObjects(std::string label, const LevelDef& level, std::vector<ObjectRef> refs);

/// The level's own properties (everything but its blocks, pigs and terrain) set from `after`. Merges with a later
/// edit under the same merge key.
std::unique_ptr<EditCommand> makeSetProperties(std::string label, const LevelDef& before, const LevelDef& after,
                                               std::string mergeKey);

} // namespace abalike

#include "edit/EditCommand.hpp"

#include <algorithm>
#include <stdexcept>

namespace abalike
{

namespace
{

class ChangeObjects final : public EditCommand
{
public:
    ChangeObjects(std::string label, std::vector<ObjectRef> refs, std::vector<ObjectDef> before,
                  std::vector<ObjectDef> after, std::string mergeKey)
        : m_label(std::move(label)), m_refs(std::move(refs)), m_before(std::move(before)), m_after(std::move(after)),
          m_mergeKey(std::move(mergeKey))
    {
        if (m_refs.size() != m_before.size() || m_refs.size() != m_after.size())
            throw std::invalid_argument("ChangeObjects: one before and one after value per object");
    }

    void apply(LevelDef& level) const override
    {
        for (std::size_t i = 0; i < m_refs.size(); ++i)
            setObjectDef(level, m_refs[i], m_after[i]);
    }
    void revert(LevelDef& level) const override
    {
        for (std::size_t i = m_refs.size(); i-- > 0;)
            setObjectDef(level, m_refs[i], m_before[i]);
    }
    std::string label() const override { return m_label; }
    std::optional<std::vector<ObjectRef>> selectionAfter() const override { return m_refs; }
    std::optional<std::vector<ObjectRef>> selectionBefore() const override { return m_refs; }
    bool merge(const EditCommand& next) override
    {
        const auto* other = dynamic_cast<const ChangeObjects*>(&next);
        if (other == nullptr || m_mergeKey.empty() || other->m_mergeKey != m_mergeKey || other->m_refs != m_refs)
            return false;
        m_after = other->m_after;
        return true;
    }

private:
    std::string m_label;
    std::vector<ObjectRef> m_refs;
    std::vector<ObjectDef> m_before;
    std::vector<ObjectDef> m_after;
    std::string m_mergeKey;
};

/// Inserting objects at given places and removing them are one edit seen from either end.
class InsertObjects final : public EditCommand
{
public:
    /// refs sorted, each the index the object has once all are inserted.
    InsertObjects(std::string label, std::vector<ObjectRef> refs, std::vector<ObjectDef> objects, bool removes)
        : m_label(std::move(label)), m_refs(std::move(refs)), m_objects(std::move(objects)), m_removes(removes)
    {
    }

    void apply(LevelDef& level) const override { m_removes ? erase(level) : insert(level); }
    void revert(LevelDef& level) const override { m_removes ? insert(level) : erase(level); }
    std::string label() const override { return m_label; }
    std::optional<std::vector<ObjectRef>> selectionAfter() const override
    {
        return m_removes ? std::vector<ObjectRef>{} : m_refs;
    }
    std::optional<std::vector<ObjectRef>> selectionBefore() const override
    {
        return m_removes ? m_refs : std::vector<ObjectRef>{};
    }

private:
    template <class T>
    static void insertInto(std::vector<T>& list, std::size_t index, const ObjectDef& def)
    {
        list.insert(list.begin() + static_cast<std::ptrdiff_t>(index), std::get<T>(def));
    }
    template <class T>
    static void eraseFrom(std::vector<T>& list, std::size_t index)
    {
        list.erase(list.begin() + static_cast<std::ptrdiff_t>(index));
    }

    /// In ascending order, so every index is right at the moment it is used.
    void insert(LevelDef& level) const
    {
        for (std::size_t i = 0; i < m_refs.size(); ++i)
        {
            const ObjectRef& ref = m_refs[i];
            if (ref.kind == ObjectKind::Block)
                insertInto(level.blocks, ref.index, m_objects[i]);
            else if (ref.kind == ObjectKind::Pig)
                insertInto(level.pigs, ref.index, m_objects[i]);
            else if (ref.kind == ObjectKind::Terrain)
                insertInto(level.terrain, ref.index, m_objects[i]);
        }
    }
    /// In descending order, for the same reason.
    void erase(LevelDef& level) const
    {
        for (std::size_t i = m_refs.size(); i-- > 0;)
        {
            const ObjectRef& ref = m_refs[i];
            if (ref.kind == ObjectKind::Block)
                eraseFrom(level.blocks, ref.index);
            else if (ref.kind == ObjectKind::Pig)
                eraseFrom(level.pigs, ref.index);
            else if (ref.kind == ObjectKind::Terrain)
                eraseFrom(level.terrain, ref.index);
        }
    }

    std::string m_label;
    std::vector<ObjectRef> m_refs;
    std::vector<ObjectDef> m_objects;
    bool m_removes;
};

/// Sets every field of a level except its object lists and its file name. `from` comes without lists (see
/// propertiesOf), so copying it is cheap; copying it whole means a field added to LevelDef is never forgotten here.
void copyProperties(const LevelDef& from, LevelDef& to)
{
    LevelDef next = from;
    next.blocks = std::move(to.blocks);
    next.pigs = std::move(to.pigs);
    next.terrain = std::move(to.terrain);
    next.sourcePath = std::move(to.sourcePath);
    to = std::move(next);
}

/// A level's properties without its object lists.
LevelDef propertiesOf(const LevelDef& level)
{
    LevelDef out = level;
    out.blocks.clear();
    out.pigs.clear();
    out.terrain.clear();
    return out;
}

class SetProperties final : public EditCommand
{
public:
    SetProperties(std::string label, LevelDef before, LevelDef after, std::string mergeKey)
        : m_label(std::move(label)), m_before(std::move(before)), m_after(std::move(after)),
          m_mergeKey(std::move(mergeKey))
    {
    }

    void apply(LevelDef& level) const override { copyProperties(m_after, level); }
    void revert(LevelDef& level) const override { copyProperties(m_before, level); }
    std::string label() const override { return m_label; }
    bool merge(const EditCommand& next) override
    {
        const auto* other = dynamic_cast<const SetProperties*>(&next);
        if (other == nullptr || m_mergeKey.empty() || other->m_mergeKey != m_mergeKey)
            return false;
        m_after = other->m_after;
        return true;
    }

private:
    std::string m_label;
    LevelDef m_before;
    LevelDef m_after;
    std::string m_mergeKey;
};

std::size_t listSize(const LevelDef& level, ObjectKind kind)
{
    switch (kind)
    {
    case ObjectKind::Block:
        return level.blocks.size();
    case ObjectKind::Pig:
        return level.pigs.size();
    case ObjectKind::Terrain:
        return level.terrain.size();
    case ObjectKind::Slingshot:
        break;
    }
    return 0;
}

} // namespace

std::unique_ptr<EditCommand> makeChangeObjects(std::string label, std::vector<ObjectRef> refs,
                                               std::vector<ObjectDef> before, std::vector<ObjectDef> after,
                                               std::string mergeKey)
{
    return std::make_unique<ChangeObjects>(std::move(label), std::move(refs), std::move(before), std::move(after),
                                           std::move(mergeKey));
}

std::unique_ptr<EditCommand> makeAddObjects(std::string label, const LevelDef& level, std::vector<ObjectDef> objects)
{
    // Appended in the order given: each kind's new objects follow that kind's existing ones.
    std::vector<std::pair<ObjectRef, ObjectDef>> items;
    std::size_t next[3] = {level.blocks.size(), level.pigs.size(), level.terrain.size()};
    for (ObjectDef& def : objects)
    {
        const ObjectKind kind = kindOf(def);
        if (kind == ObjectKind::Slingshot)
            throw std::invalid_argument("a level has one slingshot; move it instead of adding one");
        items.emplace_back(ObjectRef{kind, next[static_cast<int>(kind)]++}, std::move(def));
    }
    std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<ObjectRef> refs;
    std::vector<ObjectDef> defs;
    for (auto& [ref, def] : items)
    {
        refs.push_back(ref);
        defs.push_back(std::move(def));
    }
    return std::make_unique<InsertObjects>(std::move(label), std::move(refs), std::move(defs), false);
}

std::unique_ptr<EditCommand> makeRemoveObjects(std::string label, const LevelDef& level, std::vector<ObjectRef> refs)
{
    std::sort(refs.begin(), refs.end());
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    std::vector<ObjectRef> kept;
    std::vector<ObjectDef> defs;
    for (const ObjectRef& ref : refs)
    {
        if (ref.kind == ObjectKind::Slingshot || ref.index >= listSize(level, ref.kind))
            continue;
        kept.push_back(ref);
        defs.push_back(objectDef(level, ref));
    }
    return std::make_unique<InsertObjects>(std::move(label), std::move(kept), std::move(defs), true);
}

std::unique_ptr<EditCommand> makeSetProperties(std::string label, const LevelDef& before, const LevelDef& after,
                                               std::string mergeKey)
{
    return std::make_unique<SetProperties>(std::move(label), propertiesOf(before), propertiesOf(after),
                                           std::move(mergeKey));
}

} // namespace abalike

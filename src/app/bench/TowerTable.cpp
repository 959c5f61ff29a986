#include "bench/TowerTable.hpp"

#include "bench/ReportTable.hpp"
#include "render/TextFormat.hpp"

#include <abalike/game/GameSession.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <numeric>
#include <set>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kStoodM = 2.0;  ///< a block this far above its tower's base stood high
constexpr double kFallM = 1.0;   ///< and came down when it dropped this far
constexpr double kBesideM = 1.0; ///< a pig this close to the footprint (across) is beside it
constexpr double kTouchM = 0.05; ///< blocks this close belong to one tower
constexpr double kTarget = 0.70; ///< issue 57: share of the pigs under or beside a tower brought down

struct Box
{
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
};

Box boxOf(const b2Body& body)
{
    Box box{1e9, -1e9, 1e9, -1e9};
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
        for (int child = 0; child < fixture->GetShape()->GetChildCount(); ++child)
        {
            const b2AABB& aabb = fixture->GetAABB(child);
            box = {std::min<double>(box.left, aabb.lowerBound.x), std::max<double>(box.right, aabb.upperBound.x),
                   std::min<double>(box.bottom, aabb.lowerBound.y), std::max<double>(box.top, aabb.upperBound.y)};
        }
    return box;
}

bool touching(const Box& a, const Box& b)
{
    return a.left <= b.right + kTouchM && b.left <= a.right + kTouchM && a.bottom <= b.top + kTouchM &&
           b.bottom <= a.top + kTouchM;
}

/// A block of the level when it starts: its level index, its box and the tower it belongs to.
struct StartBlock
{
    int index = -1;
    Box box;
    int tower = -1;
};

/// The level's blocks grouped into towers: blocks that touch, directly or through others (union-find).
std::vector<StartBlock> startBlocks(const GameSession& session, std::vector<Box>& towers)
{
    std::vector<StartBlock> blocks;
    for (const Entity& e : session.world().entities())
        if (e.kind == EntityKind::Block && e.alive && e.body != nullptr)
            blocks.push_back({e.defIndex, boxOf(*e.body), -1});
    std::vector<int> parent(blocks.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&parent](int i)
    {
        while (parent[static_cast<std::size_t>(i)] != i)
            i = parent[static_cast<std::size_t>(i)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
        return i;
    };
    for (std::size_t i = 0; i < blocks.size(); ++i)
        for (std::size_t j = i + 1; j < blocks.size(); ++j)
            if (touching(blocks[i].box, blocks[j].box))
                parent[static_cast<std::size_t>(root(static_cast<int>(i)))] = root(static_cast<int>(j));
    std::vector<int> towerOfRoot(blocks.size(), -1);
    for (std::size_t i = 0; i < blocks.size(); ++i)
    {
        int& tower = towerOfRoot[static_cast<std::size_t>(root(static_cast<int>(i)))];
        if (tower < 0)
        {
            tower = static_cast<int>(towers.size());
            towers.push_back(blocks[i].box);
        }
        Box& t = towers[static_cast<std::size_t>(tower)];
        const Box& b = blocks[i].box;
        t = {std::min(t.left, b.left), std::max(t.right, b.right), std::min(t.bottom, b.bottom),
             std::max(t.top, b.top)};
        blocks[i].tower = tower;
    }
    return blocks;
}

/// One shot to the moment the next bird is ready (or the level ends): the pigs under or beside the towers it
/// brought down, and how many of them it defeated.
TowerCounts playShot(const LevelDef& level, double angleDeg, double share)
{
    GameSession session(level);
    std::vector<Box> towers;
    const std::vector<StartBlock> blocks = startBlocks(session, towers);
    std::vector<double> lowest(blocks.size());
    std::vector<int> slotOf(level.blocks.size(), -1); // the level's block index -> its place in blocks
    for (std::size_t i = 0; i < blocks.size(); ++i)
    {
        lowest[i] = blocks[i].box.bottom;
        if (blocks[i].index >= 0 && static_cast<std::size_t>(blocks[i].index) < slotOf.size())
            slotOf[static_cast<std::size_t>(blocks[i].index)] = static_cast<int>(i);
    }
    const auto slot = [&slotOf](int index)
    {
        return index >= 0 && static_cast<std::size_t>(index) < slotOf.size() ? slotOf[static_cast<std::size_t>(index)]
                                                                             : -1;
    };
    std::vector<std::pair<int, b2Vec2>> pigs; // level index, centre when the level starts
    for (const Entity& e : session.world().entities())
        if (e.kind == EntityKind::Pig && e.alive && e.body != nullptr)
            pigs.emplace_back(e.defIndex, e.body->GetPosition());

    session.launch(angleDeg, share * session.maxLaunchSpeed());
    while (session.phase() == Phase::Flying)
    {
        session.step();
        for (const Entity& e : session.world().entities())
            if (const int i = slot(e.defIndex); e.kind == EntityKind::Block && e.alive && e.body != nullptr && i >= 0)
                lowest[static_cast<std::size_t>(i)] =
                    std::min(lowest[static_cast<std::size_t>(i)], boxOf(*e.body).bottom);
    }
    // A block that broke counts where it broke (its centre then, less half its height at the start).
    for (const DestroyedEvent& d : session.destroyed())
        if (const int i = slot(d.index); d.kind == EntityKind::Block && i >= 0)
        {
            const Box& b = blocks[static_cast<std::size_t>(i)].box;
            double& low = lowest[static_cast<std::size_t>(i)];
            low = std::min(low, d.y - 0.5 * (b.top - b.bottom));
        }

    std::set<int> down;
    for (std::size_t i = 0; i < blocks.size(); ++i)
    {
        const Box& tower = towers[static_cast<std::size_t>(blocks[i].tower)];
        if (blocks[i].box.bottom - tower.bottom >= kStoodM - 1e-9 && blocks[i].box.bottom - lowest[i] >= kFallM)
            down.insert(blocks[i].tower);
    }
    TowerCounts counts;
    counts.shots = 1;
    counts.towersDown = down.empty() ? 0 : 1;
    for (const auto& [index, centre] : pigs)
    {
        const bool near =
            std::any_of(down.begin(), down.end(),
                        [&, c = centre](int t)
                        {
                            const Box& tower = towers[static_cast<std::size_t>(t)];
                            return c.x >= tower.left - kBesideM && c.x <= tower.right + kBesideM && c.y < tower.top;
                        });
        if (!near)
            continue;
        ++counts.pigsNear;
        const int pig = index;
        counts.pigsDefeated +=
            std::any_of(session.destroyed().begin(), session.destroyed().end(),
                        [pig](const DestroyedEvent& d) { return d.kind == EntityKind::Pig && d.index == pig; })
                ? 1
                : 0;
    }
    return counts;
}

void add(TowerCounts& into, const TowerCounts& shot)
{
    into.shots += shot.shots;
    into.towersDown += shot.towersDown;
    into.pigsNear += shot.pigsNear;
    into.pigsDefeated += shot.pigsDefeated;
}

} // namespace

TowerTable measureTowers(const std::vector<LevelDef>& levels, int angleStepDeg)
{
    TowerTable table;
    for (const LevelDef& level : levels)
    {
        if (table.byEpisode.empty() || table.byEpisode.back().first != level.episode)
            table.byEpisode.emplace_back(level.episode, TowerCounts{});
        for (int angle = 0; angle <= 60; angle += angleStepDeg)
            for (const double share : {0.70, 0.85, 1.00})
            {
                const TowerCounts shot = playShot(level, angle, share);
                add(table.all, shot);
                add(table.byEpisode.back().second, shot);
            }
    }
    return table;
}

std::string towerTableMarkdown(const TowerTable& table)
{
    std::ostringstream md;
    md << "| episode | shots | bring a tower down | pigs under or beside | of those, defeated | target |\n"
       << "|---|---:|---:|---:|---:|---|\n";
    const auto row = [&md](const std::string& name, const TowerCounts& c, bool withTarget)
    {
        const bool met = c.pigsNear > 0 && c.pigsDefeated >= kTarget * c.pigsNear;
        md << "| " << name << " | " << c.shots << " | " << c.towersDown << " | " << c.pigsNear << " | "
           << percentOf(c.pigsDefeated, c.pigsNear) << " | "
           << (withTarget ? ">= " + formatFixed(100.0 * kTarget, 0) + " %: **" + (met ? "met" : "missed") + "**"
                          : std::string("-"))
           << " |\n";
    };
    for (const auto& [episode, counts] : table.byEpisode)
        row(episode.empty() ? "-" : episode, counts, false);
    row("all", table.all, true);
    return md.str();
}

} // namespace abalike::app

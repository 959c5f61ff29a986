#include "bench/HitTable.hpp"

#include "bench/ReportTable.hpp"
#include "render/TextFormat.hpp"

#include <abalike/game/GameSession.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <optional>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kBreakWithinS = 0.5;
constexpr const char* kBlastRow = "black (blast at contact)";

/// A target of the table: a bird into a material breaks at least (or, as a counter-target, at most) this share.
struct HitTarget
{
    const char* bird;
    const char* material;
    double share;
    bool atLeast;
};

constexpr HitTarget kTargets[] = {
    {"red", "wood", 0.80, true},  {"yellow", "wood", 0.80, true},   {"red", "ice", 0.85, true},
    {"blue", "ice", 0.95, true},  {"yellow", "ice", 0.85, true},    {"black", "ice", 0.85, true},
    {"white", "ice", 0.85, true}, {kBlastRow, "stone", 0.95, true}, {"red", "stone", 0.10, false},
};

/// One shot: its strike, if its first contact was a block.
struct Strike
{
    std::string material;
    std::string piece;
    bool broke = false;
    bool keepsGoing = false;
};

std::optional<Strike> playStrike(const LevelDef& level, double angleDeg, double share, bool blastAtContact)
{
    GameSession session(level);
    session.launch(angleDeg, share * session.maxLaunchSpeed());
    std::optional<Strike> strike;
    int block = -1;
    double contactS = 0.0;
    double vxBefore = 0.0;
    std::size_t seen = 0;
    while (session.phase() == Phase::Flying)
    {
        session.step();
        const ShotRecord& shot = session.shots().front();
        if (!strike)
        {
            if (!shot.actualContact)
                continue;
            if (shot.firstTouched != EntityKind::Block || !shot.impact)
                return std::nullopt;
            block = shot.impact->bodyIndex;
            strike =
                Strike{shot.impact->bodyType,
                       strikePiece(session.world().entities()[static_cast<std::size_t>(block)], shot.actualContact->y)};
            contactS = session.simTime();
            vxBefore = shot.impact->birdBefore.vx;
            if (blastAtContact && session.canActivateAbility())
                session.activateAbility();
        }
        for (; seen < session.destroyed().size(); ++seen)
        {
            const DestroyedEvent& event = session.destroyed()[seen];
            if (event.kind != EntityKind::Block || event.index != block)
                continue;
            strike->broke = true;
            const Entity* after = session.world().bird();
            const double vxAfter =
                after != nullptr && after->body != nullptr ? after->body->GetLinearVelocity().x : 0.0;
            strike->keepsGoing = vxBefore * vxAfter > 0.0;
            return strike;
        }
        if (session.simTime() - contactS >= kBreakWithinS - 1e-9)
            return strike;
    }
    return strike;
}

} // namespace

std::string strikePiece(const Entity& block, double contactY)
{
    if (block.shape == BlockShape::HollowBox)
        return "hollow box";
    if (block.shape == BlockShape::Box && block.heightM >= 2.0 * block.widthM)
        return "post";
    if (block.shape == BlockShape::Box && block.widthM >= 2.0 * block.heightM)
    {
        // A flat plank (turned less than 45 degrees): struck on its upper face, it is a roof.
        const double y = block.body != nullptr ? block.body->GetPosition().y : 0.0;
        return contactY >= y + 0.25 * block.heightM ? "roof" : "plank end";
    }
    return "block";
}

HitTable measureHits(const std::vector<LevelDef>& levels, int angleStepDeg)
{
    HitTable table;
    for (const LevelDef& level : levels)
    {
        std::vector<std::string> kinds = level.birds;
        std::sort(kinds.begin(), kinds.end());
        kinds.erase(std::unique(kinds.begin(), kinds.end()), kinds.end());
        for (const std::string& kind : kinds)
        {
            LevelDef first = level;
            first.birds = {kind};
            for (const bool blast : {false, true})
            {
                if (blast && kind != "black")
                    continue;
                for (int angle = 0; angle <= 60; angle += angleStepDeg)
                    for (const double share : {0.70, 0.85, 1.00})
                    {
                        ++table.shots;
                        const std::optional<Strike> strike = playStrike(first, angle, share, blast);
                        if (!strike)
                            continue;
                        const std::string row = blast ? kBlastRow : kind;
                        for (HitCounts* counts : {&table.counts[{row, strike->material}],
                                                  &table.byPiece[{row, strike->material, strike->piece}]})
                        {
                            ++counts->strikes;
                            counts->breaks += strike->broke ? 1 : 0;
                            counts->keepsGoing += strike->broke && strike->keepsGoing ? 1 : 0;
                        }
                    }
            }
        }
    }
    return table;
}

std::string hitTableMarkdown(const HitTable& table)
{
    std::ostringstream md;
    md << "| bird | material | strikes | break within 0.5 s | of those, the bird keeps going | target |\n"
       << "|---|---|---:|---:|---:|---|\n";
    for (const auto& [key, counts] : table.counts)
    {
        std::string target = "-";
        for (const HitTarget& t : kTargets)
            if (key.first == t.bird && key.second == t.material)
            {
                const double share = counts.strikes > 0 ? static_cast<double>(counts.breaks) / counts.strikes : 0.0;
                const bool met = counts.strikes > 0 && (t.atLeast ? share >= t.share : share <= t.share);
                target = std::string(t.atLeast ? ">= " : "<= ") + formatFixed(100.0 * t.share, 0) + " %: **" +
                         (met ? "met" : "missed") + "**";
            }
        md << "| " << key.first << " | " << key.second << " | " << counts.strikes << " | "
           << percentOf(counts.breaks, counts.strikes) << " | " << percentOf(counts.keepsGoing, counts.breaks) << " | "
           << target << " |\n";
    }
    // The player's complaint: posts, plank ends and hollow boxes bounce, only roofs give way. The targets' rows by
    // the piece struck (the black bird's blast breaks whatever it touches: left out).
    md << "\nBy the piece struck (a roof is a flat plank struck on its upper face; a post stands at least twice as "
          "tall as wide):\n\n"
       << "| bird | material | piece | strikes | break within 0.5 s |\n|---|---|---|---:|---:|\n";
    for (const auto& [key, counts] : table.byPiece)
    {
        // Named copies, not structured bindings: clang 14 (the sanitizer build) cannot capture those in a lambda.
        const std::string& bird = std::get<0>(key);
        const std::string& material = std::get<1>(key);
        const std::string& piece = std::get<2>(key);
        const bool targeted =
            std::any_of(std::begin(kTargets), std::end(kTargets),
                        [&](const HitTarget& t) { return bird == t.bird && material == t.material && t.atLeast; });
        if (targeted && bird != kBlastRow)
            md << "| " << bird << " | " << material << " | " << piece << " | " << counts.strikes << " | "
               << percentOf(counts.breaks, counts.strikes) << " |\n";
    }
    return md.str();
}

} // namespace abalike::app

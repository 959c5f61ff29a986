#include "audio/SoundLayer.hpp"

#include "shell/AppContext.hpp"
#include "shell/PlayerSettings.hpp"

#include <abalike/save/Settings.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{

constexpr double kStretchEveryS = 0.35;  ///< one creak per this long while the aim keeps changing
constexpr double kImpactEveryS = 0.08;   ///< a collapse is a clatter, not a hundred overlapping knocks
constexpr double kImpactFraction = 0.05; ///< a hit must take this much of a body's health to be heard

} // namespace

void SoundLayer::remember(const GameSession& session)
{
    m_shots = session.shots().size();
    m_seen = session.destroyed().size();
    m_phase = session.phase();
    const std::vector<Entity>& entities = session.world().entities();
    m_health.resize(entities.size());
    for (std::size_t i = 0; i < entities.size(); ++i)
        m_health[i] = entities[i].health;
}

void SoundLayer::onLevelStart(PlayView& view)
{
    remember(view.session());
    m_lastSpeedMps = -1.0;
}

void SoundLayer::afterStep(PlayView& view)
{
    const GameSession& session = view.session();
    const Settings& settings = view.app().settings().current();
    if (session.destroyed().size() < m_seen || session.shots().size() < m_shots) // restarted
    {
        remember(session);
        return;
    }
    if (session.shots().size() > m_shots)
        m_board.play(SoundEffect::Launch, settings);

    bool pig = false;
    bool broke = false;
    for (std::size_t i = m_seen; i < session.destroyed().size(); ++i)
    {
        const DestroyedEvent& event = session.destroyed()[i];
        pig = pig || event.kind == EntityKind::Pig;
        broke = broke || (event.kind == EntityKind::Block && event.points > 0);
    }
    // One of each per step: ten blocks breaking in the same step are one louder crash, not ten.
    if (broke)
        m_board.play(SoundEffect::Break, settings);
    if (pig)
        m_board.play(SoundEffect::PigDefeated, settings);

    if (m_sinceImpactS >= kImpactEveryS)
    {
        const std::vector<Entity>& entities = session.world().entities();
        double hardest = 0.0;
        const Entity* hit = nullptr;
        for (std::size_t i = 0; i < entities.size() && i < m_health.size(); ++i)
        {
            const Entity& entity = entities[i];
            if (entity.kind != EntityKind::Block || !entity.alive || entity.maxHealth <= 0.0)
                continue;
            const double lost = (m_health[i] - entity.health) / entity.maxHealth;
            if (lost > hardest)
            {
                hardest = lost;
                hit = &entity;
            }
        }
        const Material* material = hit != nullptr ? session.catalog().findMaterial(hit->typeName) : nullptr;
        if (material != nullptr && hardest >= kImpactFraction)
        {
            m_board.play(impactEffectFor(material->look.surface), settings, static_cast<float>(0.4 + 2.0 * hardest));
            m_sinceImpactS = 0.0;
        }
    }

    if (session.phase() != m_phase && session.phase() == Phase::Won)
        m_board.play(SoundEffect::Win, settings);
    else if (session.phase() != m_phase && session.phase() == Phase::Lost)
        m_board.play(SoundEffect::Lose, settings);
    remember(session);
}

void SoundLayer::frameUpdate(PlayView& view, double frameS)
{
    m_sinceStretchS += frameS;
    m_sinceImpactS += frameS;
    const std::optional<AimReadout> aim = view.aim();
    if (!aim || view.session().phase() != Phase::Aiming)
    {
        m_lastSpeedMps = -1.0;
        return;
    }
    // The band creaks while the pull grows, by mouse or keys (not when a bird first sits in the slingshot).
    if (m_lastSpeedMps >= 0.0 && aim->speedMps > m_lastSpeedMps + 0.5 && m_sinceStretchS >= kStretchEveryS)
    {
        m_board.play(SoundEffect::Stretch, view.app().settings().current(), 0.6f);
        m_sinceStretchS = 0.0;
    }
    m_lastSpeedMps = aim->speedMps;
}

} // namespace abalike::app

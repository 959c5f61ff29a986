#include "fx/FxLayer.hpp"

#include "render/AbilityLook.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/Text.hpp>
#include <abalike/save/Settings.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{

constexpr float kPopUpLifeS = 1.2f;
constexpr float kPopUpRiseMps = 1.2f;

/// How hard a break shakes the view: heavy things more, and nothing for what only fell off the world.
float shakeKickPx(const DestroyedEvent& event, const Material* material)
{
    if (event.points <= 0)
        return 0.0f;
    if (event.kind == EntityKind::Pig)
        return 3.0f;
    switch (material != nullptr ? material->look.surface : SurfaceKind::Crate)
    {
    case SurfaceKind::Masonry:
        return 5.0f;
    case SurfaceKind::Grain:
        return 2.0f;
    case SurfaceKind::Frost:
    case SurfaceKind::Crate:
        break;
    }
    return 1.0f;
}
/// What an ability's look sets off, in this layer's particles and shake.
class Effects final : public AbilityEffects
{
public:
    Effects(Particles& particles, CameraShake& shake, bool reduced)
        : m_particles(particles), m_shake(shake), m_reduced(reduced)
    {
    }
    void burst(sf::Vector2f centreM, float radiusM) override
    {
        m_particles.burstBlast(centreM, radiusM, m_reduced ? 4 : 16);
    }
    void shake(float px) override
    {
        if (!m_reduced)
            m_shake.kick(px);
    }

private:
    Particles& m_particles;
    CameraShake& m_shake;
    bool m_reduced;
};

} // namespace

void FxLayer::onLevelStart(PlayView& view)
{
    m_particles.reset();
    m_particles.setFloor(static_cast<float>(view.session().level().groundY));
    m_popUps.clear();
    m_seen = view.session().destroyed().size();
    m_abilitiesSeen = view.session().shots().size();
    m_blastsSeen = view.session().blasts().size();
    m_shake.reset();
}

void FxLayer::afterStep(PlayView& view)
{
    const std::vector<DestroyedEvent>& destroyed = view.session().destroyed();
    if (destroyed.size() < m_seen) // the session restarted without telling us
        m_seen = 0;
    const bool reduced = view.app().settings().current().reducedMotion;
    for (std::size_t i = m_seen; i < destroyed.size(); ++i)
    {
        const DestroyedEvent& event = destroyed[i];
        const sf::Vector2f at(static_cast<float>(event.x), static_cast<float>(event.y));
        const Material* material =
            event.kind == EntityKind::Block ? view.session().catalog().findMaterial(event.typeName) : nullptr;
        if (material != nullptr && event.points > 0) // unscored: fell off the world, not broken
            m_particles.burstBlock(material->look, at, 0.6f, reduced ? 4 : 16);
        else if (event.kind == EntityKind::Pig)
            m_particles.burstPig(at, 0.5f, reduced ? 3 : 12);
        else if (event.kind == EntityKind::Bird) // a bird leaving after its shot
            m_particles.burstBird(at, 0.35f, reduced ? 2 : 8);
        if (!reduced)
            m_shake.kick(shakeKickPx(event, material));
        if (event.points > 0)
        {
            // append, not "+" + to_string(): GCC 12 warns falsely (-Wrestrict) on operator+ with a temporary.
            std::string text = "+";
            text.append(std::to_string(event.points));
            PopUp& popUp = m_popUps.emplace_back(PopUp{at, 0.0f, event.kind == EntityKind::Pig, sf::Text()});
            popUp.label.setString(text);
            popUp.label.setStyle(sf::Text::Bold);
            popUp.label.setOutlineThickness(2.0f);
        }
    }
    m_seen = destroyed.size();

    // An ability's use shows as its look says (the black bird's blast flashes and shakes), once per shot.
    const std::vector<ShotRecord>& shots = view.session().shots();
    if (shots.size() < m_abilitiesSeen)
        m_abilitiesSeen = 0;
    if (shots.size() > m_abilitiesSeen && shots.back().ability)
    {
        const AbilityUse& use = *shots.back().ability;
        Effects effects(m_particles, m_shake, reduced);
        abilityLook(use.ability).onUse(effects, use);
        m_abilitiesSeen = shots.size();
    }
    // TNT: a flash as wide as the blast, and a shake.
    const std::vector<BlastEvent>& blasts = view.session().blasts();
    if (blasts.size() < m_blastsSeen)
        m_blastsSeen = 0;
    for (std::size_t i = m_blastsSeen; i < blasts.size(); ++i)
    {
        const BlastEvent& blast = blasts[i];
        m_particles.burstBlast({static_cast<float>(blast.x), static_cast<float>(blast.y)},
                               static_cast<float>(blast.radiusM), reduced ? 4 : 16);
        if (!reduced)
            m_shake.kick(10.0f);
    }
    m_blastsSeen = blasts.size();
}

sf::Vector2f FxLayer::worldShakePx(PlayView& view) const
{
    return m_shake.offsetPx() * view.app().ui().scale();
}

void FxLayer::frameUpdate(PlayView& view, double frameS)
{
    (void)view;
    // A long frame (a stall, a breakpoint) must not throw every piece out of the window at once.
    const float dtS = static_cast<float>(std::min(frameS, 0.1));
    m_shake.update(dtS);
    m_particles.update(dtS);
    for (PopUp& popUp : m_popUps)
        popUp.ageS += dtS;
    std::erase_if(m_popUps, [](const PopUp& popUp) { return popUp.ageS >= kPopUpLifeS; });
}

void FxLayer::drawWorld(sf::RenderTarget& target, PlayView& view)
{
    const Camera& camera = view.camera();
    m_mesh.clear();
    m_particles.paint(m_mesh);
    m_mesh.draw(target, camera.transform());
}

void FxLayer::drawScreen(sf::RenderTarget& target, PlayView& view)
{
    // Points over the HUD and the labels, so a panel never hides them.
    const Camera& camera = view.camera();
    const sf::Font* font = view.app().ui().font();
    if (font == nullptr)
        return;
    const bool reduced = view.app().settings().current().reducedMotion;
    for (PopUp& popUp : m_popUps)
    {
        const float along = popUp.ageS / kPopUpLifeS;
        sf::Vector2f at = popUp.positionM;
        if (!reduced)
            at.y += kPopUpRiseMps * popUp.ageS;
        sf::Text& text = popUp.label;
        text.setFont(*font);
        text.setCharacterSize(view.app().ui().textSize(popUp.pig ? 26.0f : 18.0f));
        const float alpha = std::clamp((1.0f - along) / 0.3f, 0.0f, 1.0f);
        text.setFillColor(faded(popUp.pig ? palette::kStar : palette::kText, alpha));
        text.setOutlineColor(faded(sf::Color(30, 24, 16), alpha));
        const sf::FloatRect bounds = text.getLocalBounds();
        text.setOrigin(bounds.left + bounds.width / 2.0f, bounds.top + bounds.height / 2.0f);
        const sf::Vector2f screen = camera.toScreen(at);
        text.setPosition(std::round(screen.x), std::round(screen.y));
        target.draw(text);
    }
}

} // namespace abalike::app

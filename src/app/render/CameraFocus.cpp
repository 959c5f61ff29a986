#include "render/CameraFocus.hpp"

#include "render/CameraFit.hpp"

#include <algorithm>
#include <box2d/box2d.h>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr float kStructureReachM = 8.0f; ///< targets this far beyond the aimed-at stretch still count
constexpr float kLookAheadS = 2.0f;      ///< without a predicted contact, the stretch the bird covers in this time
constexpr float kMovingMps = 0.3f;       ///< faster than this a block or pig is part of the action
constexpr float kSpinningRadps = 0.5f;
constexpr float kSettlingMps = 3.0f;
constexpr float kSettlingRadps = 2.0f * kSettlingMps;

WorldBox entityBox(const Entity& entity)
{
    const b2Vec2 p = entity.body->GetPosition();
    // Half the diagonal bounds the body whatever its angle.
    const auto half = static_cast<float>(0.5 * std::hypot(entity.widthM, std::max(entity.heightM, entity.widthM)));
    return WorldBox::around({p.x, p.y}, half);
}
} // namespace

CameraFocus cameraFocusOf(const GameSession& session)
{
    CameraFocus focus;
    focus.home = levelHomeBox(session.level(), session.catalog());
    focus.groundY = static_cast<float>(session.level().groundY);
    const Vec2 pouch = session.launchPoint();
    focus.pouchM = sf::Vector2f(static_cast<float>(pouch.x), static_cast<float>(pouch.y));
    for (const PigDef& pig : session.level().pigs)
        if (const PigType* type = session.catalog().findPig(pig.type))
        {
            const auto diameter = static_cast<float>(2.0 * type->radiusM);
            focus.smallestPigM = focus.smallestPigM > 0.0f ? std::min(focus.smallestPigM, diameter) : diameter;
        }
    focus.shotUnderWay = session.phase() == Phase::Flying;
    if (!focus.shotUnderWay)
        return focus;

    const GameWorld& world = session.world();
    const ShotRecord& latest = session.shots().back();
    // A payload (the white bird's egg) is the shot's story from the moment it is laid: the camera follows it down and
    // what it sets moving, not the emptied bird climbing away.
    const auto isPayload = [](const Entity& entity)
    {
        return entity.kind == EntityKind::Bird && !entity.shotBird;
    };
    const bool payloadLaid = std::any_of(world.entities().begin(), world.entities().end(), isPayload);
    if (latest.actualContact || latest.contactTimeS || payloadLaid)
    {
        // After the first contact: the action, not the bird that caused it (a rolling bird is no story).
        focus.afterImpact = true;
        std::vector<sf::Vector2f> moving;
        bool nearlyStill = true; // nothing faster than kSettlingMps: the world is about to be calm
        for (const Entity& entity : world.entities())
            if (isPayload(entity) && entity.alive && entity.body != nullptr)
            {
                focus.action.push_back(entityBox(entity));
                moving.push_back({entity.body->GetPosition().x, entity.body->GetPosition().y});
                nearlyStill = false;
            }
        for (const Entity& entity : world.entities())
        {
            if (!entity.alive || entity.body == nullptr ||
                (entity.kind != EntityKind::Block && entity.kind != EntityKind::Pig))
                continue;
            const b2Vec2 v = entity.body->GetLinearVelocity();
            if (entity.body->IsAwake() &&
                (std::hypot(v.x, v.y) > kSettlingMps || std::abs(entity.body->GetAngularVelocity()) > kSettlingRadps))
                nearlyStill = false;
            if (std::hypot(v.x, v.y) > kMovingMps || std::abs(entity.body->GetAngularVelocity()) > kSpinningRadps)
            {
                focus.action.push_back(entityBox(entity));
                moving.push_back({entity.body->GetPosition().x, entity.body->GetPosition().y});
            }
        }
        for (const Entity& entity : world.entities())
        {
            if (!entity.alive || entity.body == nullptr || entity.kind != EntityKind::Pig)
                continue;
            const b2Vec2 p = entity.body->GetPosition();
            const bool near =
                std::any_of(moving.begin(), moving.end(),
                            [&](sf::Vector2f m) { return std::hypot(m.x - p.x, m.y - p.y) <= kActionReachM; });
            if (near)
            {
                focus.actionPigs.push_back(entityBox(entity));
                focus.action.push_back(focus.actionPigs.back());
            }
        }
        // The next bird is ready kReadyAfterContactS after the contact at the latest (or sooner, once all is calm).
        const double sinceContact = latest.contactTimeS ? world.time() - *latest.contactTimeS : 0.0;
        focus.settling = nearlyStill;
        focus.birdDue = sinceContact >= GameSession::kReadyAfterContactS - kReturnHomeS - 1e-9;
        return focus;
    }
    const Entity* bird = world.bird();
    if (bird != nullptr && bird->body != nullptr)
    {
        focus.birdDiameterM = static_cast<float>(bird->widthM);
        focus.birds.push_back(entityBox(*bird));
        const b2Vec2 v = bird->body->GetLinearVelocity();
        focus.birdVelocityMps = {v.x, v.y};
    }
    for (const Entity& entity : world.entities())
        if (entity.kind == EntityKind::Bird && entity.alive && entity.body != nullptr && &entity != bird)
            focus.birds.push_back(entityBox(entity));

    // The stretch of ground the shot is about: from the bird to where it was predicted to hit (or where it is
    // heading), widened a little; every standing block and pig on it is "the structure".
    float from = 0.0f;
    float to = 0.0f;
    if (!focus.birds.empty())
    {
        from = to = focus.birds.front().centre().x;
        const ShotRecord& shot = session.shots().back();
        const float aimX = shot.predictedContact && !shot.actualContact ? static_cast<float>(shot.predictedContact->x)
                                                                        : from + focus.birdVelocityMps.x * kLookAheadS;
        from = std::min(from, aimX);
        to = std::max(to, aimX);
    }
    else
    {
        // The bird has left the world; the shot is about whatever is still falling where it was.
        from = focus.home.left;
        to = focus.home.right;
    }
    from -= kStructureReachM;
    to += kStructureReachM;
    for (const Entity& entity : world.entities())
    {
        if (!entity.alive || entity.body == nullptr ||
            (entity.kind != EntityKind::Block && entity.kind != EntityKind::Pig))
            continue;
        const WorldBox box = entityBox(entity);
        if (box.right < from || box.left > to)
            continue;
        focus.structure = focus.structure ? focus.structure->united(box) : box;
    }
    return focus;
}

} // namespace abalike::app

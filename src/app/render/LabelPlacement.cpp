#include "render/LabelPlacement.hpp"

#include <algorithm>
#include <array>
#include <box2d/box2d.h>
#include <cmath>
#include <limits>

namespace abalike::app
{

namespace
{
/// Calls visit(name, rect) for the slingshot with the bird it holds, the bird in flight, the last shot's landing point
/// (its first contact) and, with pigs, every live pig:
/// one walk for both the per-frame placement boxes (which list pigs with the blocks) and the trace's named boxes.
template <class Visit>
void forEachKeepVisible(const GameSession& session, const Camera& camera, bool pigs, Visit&& visit)
{
    const auto box = [&camera, &visit](const char* name, double left, double top, double right, double bottom)
    {
        const sf::Vector2f topLeft = camera.toScreen({static_cast<float>(left), static_cast<float>(top)});
        const sf::Vector2f bottomRight = camera.toScreen({static_cast<float>(right), static_cast<float>(bottom)});
        visit(name, sf::FloatRect(topLeft, bottomRight - topLeft));
    };
    // The slingshot with the bird it holds: its pouch and a post's length under it.
    const Vec2 pouch = session.launchPoint();
    box("slingshot", pouch.x - 0.8, pouch.y + 0.8, pouch.x + 0.8, pouch.y - 1.6);
    if (const Entity* bird = session.world().bird(); bird != nullptr && bird->body != nullptr)
    {
        const b2Vec2 p = bird->body->GetPosition();
        const double r = 0.5 * bird->widthM;
        box("bird", p.x - r, p.y + r, p.x + r, p.y - r);
    }
    // Where the last shot's bird first struck: the after-shot sentence and the predicted-vs-actual mark talk about it.
    if (!session.shots().empty())
        if (const std::optional<ContactPoint>& landing = session.shots().back().actualContact)
            box("landing point", landing->x - 0.4, landing->y + 0.4, landing->x + 0.4, landing->y - 0.4);
    if (!pigs)
        return;
    for (const Entity& pig : session.world().entities())
        if (pig.alive && pig.body != nullptr && pig.kind == EntityKind::Pig)
        {
            const b2Vec2 p = pig.body->GetPosition();
            const double r = 0.5 * pig.widthM;
            box("pig", p.x - r, p.y + r, p.x + r, p.y - r);
        }
}
} // namespace

std::vector<sf::FloatRect> structureScreenBoxes(const GameSession& session, const Camera& camera)
{
    std::vector<sf::FloatRect> boxes;
    for (const Entity& entity : session.world().entities())
    {
        if (!entity.alive || entity.body == nullptr ||
            (entity.kind != EntityKind::Block && entity.kind != EntityKind::Pig))
            continue;
        const b2Vec2 p = entity.body->GetPosition();
        // Half the diagonal bounds the body whatever its angle.
        const auto half = static_cast<float>(0.5 * std::hypot(entity.widthM, std::max(entity.heightM, entity.widthM)));
        const sf::Vector2f topLeft = camera.toScreen({p.x - half, p.y + half});
        const sf::Vector2f bottomRight = camera.toScreen({p.x + half, p.y - half});
        boxes.emplace_back(topLeft, bottomRight - topLeft);
    }
    forEachKeepVisible(session, camera, false,
                       [&boxes](const char*, const sf::FloatRect& rect) { boxes.push_back(rect); });
    return boxes;
}

std::vector<ScreenRegion> keepVisibleBoxes(const GameSession& session, const Camera& camera)
{
    std::vector<ScreenRegion> boxes;
    forEachKeepVisible(session, camera, true,
                       [&boxes](const char* name, const sf::FloatRect& rect) {
                           boxes.push_back({name, rect});
                       });
    return boxes;
}

float coveredArea(const sf::FloatRect& rect, std::span<const sf::FloatRect> boxes)
{
    float area = 0.0f;
    sf::FloatRect overlap;
    for (const sf::FloatRect& box : boxes)
        if (rect.intersects(box, overlap))
            area += overlap.width * overlap.height;
    return area;
}

sf::Vector2f placeLabel(sf::Vector2f anchor, sf::Vector2f size, sf::Vector2f window,
                        std::span<const sf::FloatRect> avoid, float gap)
{
    const std::vector<sf::Vector2f> spots{
        {anchor.x + gap, anchor.y - gap - size.y},                  // above right
        {anchor.x - gap - size.x, anchor.y - gap - size.y},         // above left
        {anchor.x + gap, anchor.y - 0.5f * size.y},                 // right
        {anchor.x - gap - size.x, anchor.y - 0.5f * size.y},        // left
        {anchor.x - 0.5f * size.x, anchor.y - 3.0f * gap - size.y}, // higher up
        {anchor.x + gap, anchor.y - 4.0f * gap - size.y},           // higher, right
        {anchor.x - gap - size.x, anchor.y - 4.0f * gap - size.y},  // higher, left
        {anchor.x - 0.5f * size.x, anchor.y - 8.0f * gap - size.y}, // well above
        {anchor.x + gap, anchor.y + gap},                           // below right
        {anchor.x - gap - size.x, anchor.y + gap},                  // below left
    };
    sf::Vector2f best = spots.front();
    float bestCover = std::numeric_limits<float>::max();
    for (sf::Vector2f spot : spots)
    {
        // Inside the window, a few pixels from its edges.
        spot.x = std::clamp(spot.x, 4.0f, std::max(4.0f, window.x - size.x - 4.0f));
        spot.y = std::clamp(spot.y, 4.0f, std::max(4.0f, window.y - size.y - 4.0f));
        const float cover = coveredArea({spot, size}, avoid);
        if (cover <= 0.0f)
            return spot;
        if (cover < bestCover)
        {
            bestCover = cover;
            best = spot;
        }
    }
    return best;
}

} // namespace abalike::app

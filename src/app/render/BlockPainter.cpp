#include "render/BlockPainter.hpp"

#include "render/ConvexPolygon.hpp"
#include "render/DetailRandom.hpp"
#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace abalike::app
{

namespace
{
constexpr float kCrackedBelow = 0.66f;
constexpr float kBrokenBelow = 0.33f;

/// A random point inside a convex polygon: a convex combination of its vertices.
sf::Vector2f interiorPoint(std::span<const sf::Vector2f> polygon, DetailRandom& random)
{
    sf::Vector2f sum;
    float total = 0.0f;
    for (const sf::Vector2f& p : polygon)
    {
        const float w = random.unit() + 0.05f;
        sum += p * w;
        total += w;
    }
    return sum / total;
}

/// Lines along the long side of the block, broken here and there like grain.
void addGrain(Mesh& mesh, std::span<const sf::Vector2f> inner, const MaterialColours& colours, const BlockLook& look,
              DetailRandom& random)
{
    const sf::FloatRect box = convex::bounds(inner);
    const bool alongX = box.width >= box.height;
    const float across = alongX ? box.height : box.width;
    const int lines = std::clamp(static_cast<int>(across / 0.09f), 1, 7);
    const float width = std::max(0.018f, 1.0f * look.pixelM);
    for (int i = 0; i < lines; ++i)
    {
        const float f = (static_cast<float>(i) + 0.5f + random.range(-0.2f, 0.2f)) / static_cast<float>(lines);
        sf::Vector2f a =
            alongX ? sf::Vector2f(box.left, box.top + f * box.height) : sf::Vector2f(box.left + f * box.width, box.top);
        sf::Vector2f b = alongX ? sf::Vector2f(box.left + box.width, a.y) : sf::Vector2f(a.x, box.top + box.height);
        if (!convex::clipSegment(inner, a, b))
            continue;
        // One gap somewhere along the line.
        const float gapStart = random.range(0.15f, 0.75f);
        const float gapEnd = gapStart + random.range(0.05f, 0.2f);
        mesh.addLine(a, a + (b - a) * gapStart, width, colours.detail);
        mesh.addLine(a + (b - a) * std::min(gapEnd, 1.0f), b, width, colours.detail);
    }
}

/// A bright streak near the upper long edge and a short one beside it.
void addGlint(Mesh& mesh, std::span<const sf::Vector2f> inner, const MaterialColours& colours, const BlockLook& look)
{
    const sf::FloatRect box = convex::bounds(inner);
    const bool alongX = box.width >= box.height;
    const float width = std::max(0.04f, 2.0f * look.pixelM);
    const auto streak = [&](float across, float from, float to)
    {
        sf::Vector2f a = alongX ? sf::Vector2f(box.left + from * box.width, box.top + across * box.height)
                                : sf::Vector2f(box.left + across * box.width, box.top + from * box.height);
        sf::Vector2f b =
            alongX ? sf::Vector2f(box.left + to * box.width, a.y) : sf::Vector2f(a.x, box.top + to * box.height);
        if (convex::clipSegment(inner, a, b))
            mesh.addLine(a, b, width, colours.highlight);
    };
    streak(0.78f, 0.12f, 0.55f);
    streak(0.78f, 0.62f, 0.7f);
    streak(0.55f, 0.12f, 0.3f);
}

/// Speckles of two shades, placed by rejection inside the polygon.
void addSpeckles(Mesh& mesh, std::span<const sf::Vector2f> inner, const MaterialColours& colours, const BlockLook& look,
                 DetailRandom& random)
{
    const float area = convex::signedArea(inner);
    const int count = std::clamp(static_cast<int>(area / 0.025f), 3, 80);
    const sf::FloatRect box = convex::bounds(inner);
    for (int i = 0; i < count; ++i)
    {
        const sf::Vector2f p(box.left + random.unit() * box.width, box.top + random.unit() * box.height);
        if (!convex::contains(inner, p))
            continue;
        const float radius = std::max(random.range(0.018f, 0.045f), 0.8f * look.pixelM);
        mesh.addCircle(p, radius, (i % 3 == 0) ? colours.highlight : colours.detail, 8);
    }
}

/// Cracks running from the edge into the block; all points stay inside because they are convex combinations.
void addCracks(Mesh& mesh, std::span<const sf::Vector2f> inner, int count, const BlockLook& look, DetailRandom& random)
{
    const float width = std::max(0.025f, 1.3f * look.pixelM);
    const std::size_t n = inner.size();
    for (int i = 0; i < count; ++i)
    {
        const std::size_t edge = static_cast<std::size_t>(random.below(static_cast<int>(n)));
        const sf::Vector2f start = inner[edge] + (inner[(edge + 1) % n] - inner[edge]) * random.range(0.2f, 0.8f);
        const sf::Vector2f end = interiorPoint(inner, random);
        const sf::Vector2f corner = inner[static_cast<std::size_t>(random.below(static_cast<int>(n)))];
        const sf::Vector2f bend = start * 0.45f + end * 0.4f + corner * 0.15f;
        const sf::Vector2f crack[] = {start, bend, end};
        mesh.addPolyline(crack, width, palette::kCrack);
        // A short branch off the bend.
        const sf::Vector2f branch = bend * 0.6f + interiorPoint(inner, random) * 0.4f;
        mesh.addLine(bend, branch, 0.7f * width, palette::kCrack);
    }
}
/// A TNT crate: two braces across the boards and the letters TNT, stroked so they scale with the crate.
void addCrate(Mesh& mesh, std::span<const sf::Vector2f> inner, const MaterialColours& colours, const BlockLook& look)
{
    const sf::FloatRect box = convex::bounds(inner);
    const float brace = std::max(0.03f, 0.08f * std::min(box.width, box.height));
    for (const auto& [a, b] :
         {std::pair{sf::Vector2f(box.left, box.top), sf::Vector2f(box.left + box.width, box.top + box.height)},
          std::pair{sf::Vector2f(box.left, box.top + box.height), sf::Vector2f(box.left + box.width, box.top)}})
    {
        sf::Vector2f from = a;
        sf::Vector2f to = b;
        if (convex::clipSegment(inner, from, to))
            mesh.addLine(from, to, brace, colours.detail);
    }
    // Three letters side by side, each 0.6 as wide as high, in the middle of the crate (y up: the top is +y).
    const float height = std::min(0.45f * box.height, 0.8f * box.width / (3.0f * 0.6f + 2.0f * 0.15f));
    const float width = 0.6f * height;
    const float gap = 0.15f * height;
    const float stroke = std::max(1.2f * look.pixelM, 0.14f * height);
    const sf::Vector2f centre(box.left + 0.5f * box.width, box.top + 0.5f * box.height);
    const float left = centre.x - 1.5f * width - gap;
    const float bottom = centre.y - 0.5f * height;
    const float top = centre.y + 0.5f * height;
    const sf::Color ink = colours.highlight;
    const auto letterT = [&](float x)
    {
        mesh.addLine({x, top}, {x + width, top}, stroke, ink);
        mesh.addLine({x + 0.5f * width, top}, {x + 0.5f * width, bottom}, stroke, ink);
    };
    const auto letterN = [&](float x)
    {
        mesh.addLine({x, bottom}, {x, top}, stroke, ink);
        mesh.addLine({x, top}, {x + width, bottom}, stroke, ink);
        mesh.addLine({x + width, bottom}, {x + width, top}, stroke, ink);
    };
    letterT(left);
    letterN(left + width + gap);
    letterT(left + 2.0f * (width + gap));
}

/// Wood's colour-blind pattern: stripes along the block's long side.
void addStripes(Mesh& mesh, std::span<const sf::Vector2f> inner, const sf::FloatRect& box, float spacing, float width,
                sf::Color ink)
{
    if (inner.size() < 3)
        return;
    // Stripes parallel to the longer of the first two edges (a box's length), across the whole block.
    sf::Vector2f along = inner[1] - inner[0];
    const sf::Vector2f other = inner[2] - inner[1];
    if (std::hypot(other.x, other.y) > std::hypot(along.x, along.y))
        along = other;
    const float length = std::hypot(along.x, along.y);
    if (length <= 0.0f)
        return;
    along /= length;
    const sf::Vector2f normal(-along.y, along.x);
    const float reach = box.width + box.height;
    const sf::Vector2f centre(box.left + 0.5f * box.width, box.top + 0.5f * box.height);
    for (float offset = -reach; offset <= reach; offset += spacing)
    {
        sf::Vector2f a = centre + normal * offset - along * reach;
        sf::Vector2f b = centre + normal * offset + along * reach;
        if (convex::clipSegment(inner, a, b))
            mesh.addLine(a, b, width, ink);
    }
}

/// The colour-blind-safe look's patterns, so no material is told by colour alone: wood in stripes along its long
/// side, ice hatched at 45 degrees, stone dotted on a grid.
void addPattern(Mesh& mesh, std::span<const sf::Vector2f> inner, const MaterialColours& colours, const BlockLook& look)
{
    const sf::FloatRect box = convex::bounds(inner);
    const float spacing = std::max(0.1f, 7.0f * look.pixelM);
    const float width = std::max(0.025f, 1.5f * look.pixelM);
    const sf::Color ink = darken(colours.outline, 0.85f);
    switch (look.material->surface)
    {
    case SurfaceKind::Frost:
        for (float c = box.left - box.height; c < box.left + box.width; c += spacing)
        {
            sf::Vector2f a(c, box.top);
            sf::Vector2f b(c + box.height, box.top + box.height);
            if (convex::clipSegment(inner, a, b))
                mesh.addLine(a, b, width, ink);
        }
        break;
    case SurfaceKind::Masonry:
        for (float y = box.top + 0.5f * spacing; y < box.top + box.height; y += spacing)
            for (float x = box.left + 0.5f * spacing; x < box.left + box.width; x += spacing)
                if (convex::contains(inner, {x, y}))
                    mesh.addCircle({x, y}, 0.22f * spacing, ink, 8);
        break;
    case SurfaceKind::Grain:
        addStripes(mesh, inner, box, spacing, width, ink);
        break;
    case SurfaceKind::Crate:
        break;
    }
}

} // namespace

void BlockPainter::paintPolygon(Mesh& mesh, std::span<const sf::Vector2f> polygon, const BlockLook& look)
{
    MaterialColours colours = materialColours(*look.material);
    if (look.healthFraction < kBrokenBelow)
    {
        colours.fill = darken(colours.fill, 0.72f);
        colours.detail = darken(colours.detail, 0.72f);
        colours.highlight = darken(colours.highlight, 0.8f);
    }
    const float outline = std::max(0.035f, 1.5f * look.pixelM);
    std::vector<sf::Vector2f> inner = convex::inset(polygon, outline);
    if (inner.empty())
    {
        mesh.addConvex(polygon, colours.outline);
        return;
    }
    mesh.addConvex(polygon, colours.outline);
    mesh.addConvex(inner, colours.fill);

    DetailRandom random(look.seed);
    switch (look.material->surface)
    {
    case SurfaceKind::Grain:
        addGrain(mesh, inner, colours, look, random);
        break;
    case SurfaceKind::Frost:
        addGlint(mesh, inner, colours, look);
        break;
    case SurfaceKind::Masonry:
        addSpeckles(mesh, inner, colours, look, random);
        break;
    case SurfaceKind::Crate:
        addCrate(mesh, inner, colours, look);
        break;
    }

    if (activeLook().colourBlindSafe)
        addPattern(mesh, inner, colours, look);

    if (look.healthFraction < kBrokenBelow)
        addCracks(mesh, inner, 5, look, random);
    else if (look.healthFraction < kCrackedBelow)
        addCracks(mesh, inner, 2, look, random);
}

void BlockPainter::paintDisc(Mesh& mesh, sf::Vector2f centre, float radius, const BlockLook& look)
{
    const std::vector<sf::Vector2f> polygon = convex::circle(centre, radius, 28);
    paintPolygon(mesh, polygon, look);
}

} // namespace abalike::app

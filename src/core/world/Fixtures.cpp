#include "world/Fixtures.hpp"

#include "world/Skin.hpp"

#include <numbers>

namespace abalike
{

b2BodyUserData userDataFor(int entityIndex)
{
    b2BodyUserData data;
    data.pointer = static_cast<uintptr_t>(entityIndex + 1);
    return data;
}

void addPolygonFixture(b2Body* body, const std::vector<b2Vec2>& outline, const b2FixtureDef& base, float chamferM,
                       const std::vector<bool>& chamferCorners)
{
    const std::vector<b2Vec2> core = abalike::chamferCorners(insetPolygon(outline), chamferM, chamferCorners);
    b2PolygonShape shape;
    shape.Set(core.data(), static_cast<int>(core.size()));
    b2FixtureDef def = base;
    def.shape = &shape;
    body->CreateFixture(&def);
}

void addBoxFixture(b2Body* body, double w, double h, const b2FixtureDef& base, float chamferM, double cx, double cy,
                   const std::vector<bool>& chamferCorners)
{
    const auto x0 = static_cast<float>(cx - w / 2);
    const auto x1 = static_cast<float>(cx + w / 2);
    const auto y0 = static_cast<float>(cy - h / 2);
    const auto y1 = static_cast<float>(cy + h / 2);
    addPolygonFixture(body, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, base, chamferM, chamferCorners);
}

void addCircleFixture(b2Body* body, double radius, const b2FixtureDef& base)
{
    b2CircleShape circle;
    circle.m_radius = physicsCircleRadius(radius);
    b2FixtureDef def = base;
    def.shape = &circle;
    body->CreateFixture(&def);
}

void addBlockFixtures(b2Body* body, const BlockDef& block, const b2FixtureDef& base, float chamferM)
{
    const double w = block.widthM;
    const double h = block.heightM;
    switch (block.shape)
    {
    case BlockShape::Box:
        addBoxFixture(body, w, h, base, chamferM);
        break;
    case BlockShape::Circle:
        addCircleFixture(body, w / 2, base);
        break;
    case BlockShape::Triangle:
    {
        const auto hw = static_cast<float>(w / 2);
        const auto hh = static_cast<float>(h / 2);
        addPolygonFixture(body, {{-hw, -hh}, {hw, -hh}, {-hw, hh}}, base, chamferM);
        break;
    }
    case BlockShape::HollowBox:
    {
        // Four walls on one body. Top and bottom span the full width; the side walls reach into them by twice
        // the skin inset so that the walls' cores meet exactly and the frame has no notch at its corners. Only the
        // frame's own four corners are chamfered: cutting where walls meet would notch the frame.
        const double t = block.wallM;
        const double sideH = h - 2 * t + 4 * kPolygonInset;
        addBoxFixture(body, w, t, base, chamferM, 0.0, h / 2 - t / 2, {false, false, true, true});
        addBoxFixture(body, w, t, base, chamferM, 0.0, -(h / 2 - t / 2), {true, true, false, false});
        addBoxFixture(body, t, sideH, base, chamferM, -(w / 2 - t / 2), 0.0, {false, false, false, false});
        addBoxFixture(body, t, sideH, base, chamferM, w / 2 - t / 2, 0.0, {false, false, false, false});
        break;
    }
    }
}

double designedArea(const BlockDef& block)
{
    const double w = block.widthM;
    const double h = block.heightM;
    switch (block.shape)
    {
    case BlockShape::Box:
        return w * h;
    case BlockShape::Circle:
        return std::numbers::pi * w * w / 4;
    case BlockShape::Triangle:
        return w * h / 2;
    case BlockShape::HollowBox:
        return w * h - (w - 2 * block.wallM) * (h - 2 * block.wallM);
    }
    return w * h;
}

void setBodyMass(b2Body* body, double massKg)
{
    const double current = body->GetMass();
    if (!(current > 0.0))
        return;
    const auto scale = static_cast<float>(massKg / current);
    for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext())
        f->SetDensity(f->GetDensity() * scale);
    body->ResetMassData();
}

} // namespace abalike

#include <abalike/world/WorldDigest.hpp>

#include <box2d/box2d.h>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace abalike
{
namespace
{

/// FNV-1a, 64 bits: enough to tell two runs apart, and the same on every platform.
class Fnv1a
{
public:
    void add(const void* data, std::size_t size)
    {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            m_hash = (m_hash ^ bytes[i]) * 0x100000001b3ULL;
    }
    void add(double value)
    {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        add(&bits, sizeof bits);
    }
    void add(int value) { add(&value, sizeof value); }
    std::uint64_t value() const { return m_hash; }

private:
    std::uint64_t m_hash = 0xcbf29ce484222325ULL;
};

} // namespace

std::string bodiesDigest(const GameWorld& world)
{
    Fnv1a hash;
    for (const Entity& entity : world.entities())
    {
        hash.add(static_cast<int>(entity.kind));
        hash.add(entity.defIndex);
        hash.add(entity.typeName.data(), entity.typeName.size());
        hash.add(entity.alive ? 1 : 0);
        hash.add(entity.health);
        if (entity.body == nullptr)
            continue;
        const b2Vec2 position = entity.body->GetPosition();
        const b2Vec2 velocity = entity.body->GetLinearVelocity();
        for (const double value : {double(position.x), double(position.y), double(entity.body->GetAngle()),
                                   double(velocity.x), double(velocity.y), double(entity.body->GetAngularVelocity())})
            hash.add(value);
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash.value()));
    return text;
}

} // namespace abalike

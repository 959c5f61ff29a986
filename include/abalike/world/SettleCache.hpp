#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <box2d/b2_collision.h>

namespace abalike
{

/// What a world's settle step leaves behind (GameWorld::step, WorldSettings::settleIterations): every body's place
/// and velocity and every contact's manifold with the impulses Box2D warm-starts the next step from. In the order of
/// Box2D's body and contact lists.
struct SettledState
{
    struct Body
    {
        float x = 0.0f;
        float y = 0.0f;
        float angle = 0.0f;
        float vx = 0.0f;
        float vy = 0.0f;
        float spin = 0.0f;
    };
    struct Contact
    {
        std::int32_t bodyA = 0; ///< positions in the body list
        std::int32_t bodyB = 0;
        std::int32_t fixtureA = 0; ///< positions in the body's fixture list (a hollow box has four, a hill several)
        std::int32_t fixtureB = 0;
        std::int32_t childA = 0; ///< child shapes (edges of a chain)
        std::int32_t childB = 0;
        b2Manifold manifold{};
    };
    std::vector<Body> bodies;
    std::vector<Contact> contacts;
};

/// Settle steps computed once and reused: a world built from the same bodies and settings starts from the stored
/// state instead of solving its settle step again (thousands of iterations over every contact; 4 s for the
/// 1 000-block wall). Every world of the same key passes through the same restore, whether the state was just
/// computed or found here, so a level plays bit for bit the same either way (GameWorld::step).
///
/// Kept in memory for the process (the solver and the model player build the same level thousands of times) and, once
/// setDirectory() is called (the game does), in files there, so the next start of the game loads a big level at once.
/// Thread-safe.
class SettleCache
{
public:
    /// The cache every GameWorld uses.
    static SettleCache& shared();

    /// Also keeps states as files in dir (made when missing); buildId marks the program that computed them, and a
    /// file written by another build is ignored (its physics may differ). An empty dir keeps them in memory only.
    void setDirectory(const std::string& dir, const std::string& buildId);

    std::shared_ptr<const SettledState> find(std::uint64_t key);
    void store(std::uint64_t key, std::shared_ptr<const SettledState> state);

    /// Forgets every state held in memory (files stay).
    void clear();
    std::size_t size() const;

    /// States kept in memory at most; the oldest goes first.
    static constexpr std::size_t kMaxStates = 64;

private:
    std::shared_ptr<const SettledState> readFile(std::uint64_t key) const;
    void writeFile(std::uint64_t key, const SettledState& state) const;
    void remember(std::uint64_t key, std::shared_ptr<const SettledState> state);
    std::string pathOf(std::uint64_t key) const;

    mutable std::mutex m_mutex;
    std::map<std::uint64_t, std::shared_ptr<const SettledState>> m_states;
    std::deque<std::uint64_t> m_order; ///< keys, oldest first
    std::string m_dir;
    std::string m_buildId;
};

/// 64-bit FNV-1a over bytes, for SettleCache keys.
class SettleKey
{
public:
    template <typename T>
    SettleKey& add(const T& value)
    {
        const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
        for (std::size_t i = 0; i < sizeof(T); ++i)
            m_hash = (m_hash ^ bytes[i]) * 1099511628211ull;
        return *this;
    }
    SettleKey& addText(const std::string& text);
    std::uint64_t value() const { return m_hash; }

private:
    std::uint64_t m_hash = 14695981039346656037ull;
};

} // namespace abalike

#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace abalike::test
{

/// Levels drawn from the whole space the format allows (every shape, material, pig type, terrain, environment term,
/// gust form, material override, custom bird, sandbox flag, odd strings and numbers), for round-trip tests. They
/// are valid field by field; their geometry (overlaps, reach) is whatever chance makes it.
class RandomLevel
{
public:
    explicit RandomLevel(std::uint64_t seed) : m_random(seed) {}

    LevelDef next()
    {
        const Catalog& catalog = Catalog::builtin();
        LevelDef level;
        level.id = text(1);
        level.title = text(1);
        if (coin())
            level.episode = text(1);
        if (coin())
            level.lesson = text(0);
        for (int i = integer(0, 3); i > 0; --i)
            level.hints.push_back(text(0));
        level.sandbox = coin();
        if (coin())
            level.groundY = number(-50, 50);
        level.slingshot = {number(-2000, 2000), number(-2000, 2000), coin() ? 1200.0 : number(1, 1e6), std::nullopt,
                           std::nullopt};
        if (coin())
            level.customBird = CustomBirdDef{number(0.01, 5000), number(0.01, 3), number(0.04, 1.2)};
        for (int i = integer(1, 20); i > 0; --i)
        {
            const auto& birds = catalog.birds();
            const int pick = integer(0, static_cast<int>(birds.size()) - (level.customBird ? 0 : 1));
            level.birds.push_back(pick < static_cast<int>(birds.size()) ? birds[static_cast<std::size_t>(pick)].name
                                                                        : kCustomBirdName);
        }
        for (int i = integer(0, 12); i > 0; --i)
            level.blocks.push_back(block(catalog));
        for (int i = integer(level.sandbox ? 0 : 1, 6); i > 0; --i)
        {
            const auto& pigs = catalog.pigs();
            level.pigs.push_back({pigs[static_cast<std::size_t>(integer(0, static_cast<int>(pigs.size()) - 1))].name,
                                  number(-2000, 2000), number(-2000, 2000)});
        }
        for (int i = integer(0, 4); i > 0; --i)
            level.terrain.push_back(
                {number(-2000, 2000), number(-2000, 2000), number(0.1, 50), number(0.1, 50), angle(), {}});
        environment(level.environment);
        for (const auto& material : catalog.materials())
            if (coin())
            {
                MaterialOverrideDef item{material.name, {}, {}, {}, {}};
                if (coin())
                    item.densityKgPerM3 = number(50, 25000);
                if (coin())
                    item.friction = number(0, 2);
                if (coin())
                    item.restitution = number(0, 1);
                if (coin())
                    item.strengthNs = number(1, 1e6);
                level.materials.push_back(item);
            }
        const int a = integer(0, 1000000);
        const int b = a + integer(0, 1000000);
        level.starScores = {a, b, b + integer(0, 1000000)};
        if (coin())
            level.timeLimitS = number(1, 3600);
        if (coin())
            level.referenceShot = ReferenceShotDef{number(-90, 90), number(0, Catalog::builtin().maxLaunchSpeedMps())};
        return level;
    }

private:
    bool coin() { return std::uniform_int_distribution<int>(0, 1)(m_random) == 1; }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_random); }

    /// A number in [lo, hi] with a random number of decimals (0 to 17 significant digits), now and then an edge.
    double number(double lo, double hi)
    {
        switch (integer(0, 9))
        {
        case 0:
            return lo;
        case 1:
            return hi;
        default:
            break;
        }
        const double x = std::uniform_real_distribution<double>(lo, hi)(m_random);
        const int digits = integer(0, 6);
        if (digits == 6)
            return x; // every bit
        const double scale = std::pow(10.0, digits);
        return std::clamp(std::round(x * scale) / scale, lo, hi);
    }

    double angle() { return coin() ? 0.0 : number(-360, 360); }

    /// Strings with the characters JSON must escape, and text beyond ASCII.
    std::string text(int minLength)
    {
        static const char* const pieces[] = {"a", "Z", "7", " ", "\"", "\\", "/", "é",
                                             "ß", "→", "🐦", "{", "]",  ",",  ":"};
        std::string out;
        for (int i = integer(minLength, 12); i > 0; --i)
            out += pieces[integer(0, 14)];
        return out;
    }

    BlockDef block(const Catalog& catalog)
    {
        BlockDef b;
        b.shape = static_cast<BlockShape>(integer(0, 3));
        const auto& materials = catalog.materials();
        b.material = materials[static_cast<std::size_t>(integer(0, static_cast<int>(materials.size()) - 1))].name;
        b.x = number(-2000, 2000);
        b.y = number(-2000, 2000);
        b.widthM = number(0.1, 10);
        b.heightM = b.shape == BlockShape::Circle ? b.widthM : number(0.1, 10);
        b.angleDeg = angle();
        if (b.shape == BlockShape::HollowBox)
        {
            b.widthM = std::max(b.widthM, 0.2);
            b.heightM = std::max(b.heightM, 0.2);
            const double maxWall = std::max(0.05, 0.5 * std::min(b.widthM, b.heightM) - 0.05);
            b.wallM = coin() ? 0.1 : number(0.05, maxWall);
            b.wallM = std::min(b.wallM, maxWall);
        }
        return b;
    }

    void environment(EnvironmentDef& e)
    {
        if (coin())
            e.gravity = number(0, 100);
        const bool air = coin();
        if (!air)
            return;
        e.airDensity = std::max(number(0, 100), 0.001);
        if (coin())
        {
            e.windX = number(-100, 100);
            e.windY = number(-100, 100);
        }
        if (!coin())
            return;
        GustDef g;
        if (coin())
        {
            g.kind = GustDef::Kind::Steps;
            double t = 0.0;
            for (int i = integer(1, 5); i > 0; --i)
            {
                t = std::min(3600.0, t + number(0.001, 600));
                if (!g.steps.empty() && t <= g.steps.back().startS)
                    break;
                g.steps.push_back({t, number(-100, 100), number(-100, 100)});
            }
        }
        else
        {
            g.kind = GustDef::Kind::Sine;
            g.amplitudeX = number(-100, 100);
            g.amplitudeY = number(-100, 100);
            g.periodS = number(0.1, 3600);
            // Written in degrees: the loader's conversion, from a phase with at most 6 decimals.
            g.phaseRad = coin() ? 0.0 : std::round(number(-360, 360) * 1e6) / 1e6 * std::numbers::pi / 180.0;
        }
        e.gusts = g;
    }

    std::mt19937_64 m_random;
};

} // namespace abalike::test

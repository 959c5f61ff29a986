#include "fx/CameraShake.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace abalike::app;

namespace
{
float length(sf::Vector2f v)
{
    return std::hypot(v.x, v.y);
}
} // namespace

TEST(CameraShake, StillUntilKickedAndKicksAddUpToTheCap)
{
    CameraShake shake;
    EXPECT_FALSE(shake.active());
    EXPECT_EQ(shake.offsetPx(), sf::Vector2f(0.0f, 0.0f));
    shake.kick(5.0f);
    shake.kick(5.0f);
    EXPECT_TRUE(shake.active());
    shake.update(0.01);
    EXPECT_GT(length(shake.offsetPx()), 0.0f);
    for (int i = 0; i < 10; ++i)
        shake.kick(5.0f);
    shake.update(0.013);
    // Each axis is a weighted sum of two sines with weights adding to 1: never beyond the amplitude.
    EXPECT_LE(std::abs(shake.offsetPx().x), CameraShake::kMaxPx);
    EXPECT_LE(std::abs(shake.offsetPx().y), CameraShake::kMaxPx);
    shake.kick(-50.0f); // a negative kick is no kick, not a calm-down
    EXPECT_TRUE(shake.active());
}

TEST(CameraShake, DiesAwayWithinHalfASecondAtSixtyFramesPerSecond)
{
    CameraShake shake;
    shake.kick(CameraShake::kMaxPx);
    int frames = 0;
    while (shake.active() && frames < 600)
    {
        shake.update(1.0 / 60.0);
        ++frames;
    }
    // 16 px falls to 0.25 px after ln(64) * 0.12 s = 0.50 s: 30 frames.
    EXPECT_EQ(frames, 30);
    EXPECT_EQ(shake.offsetPx(), sf::Vector2f(0.0f, 0.0f));
}

TEST(CameraShake, TheSameKicksAndFramesGiveTheSameOffsets)
{
    CameraShake a;
    CameraShake b;
    a.kick(7.0f);
    b.kick(7.0f);
    for (int i = 0; i < 12; ++i)
    {
        a.update(1.0 / 60.0);
        b.update(1.0 / 60.0);
        EXPECT_EQ(a.offsetPx(), b.offsetPx());
    }
    a.reset();
    EXPECT_FALSE(a.active());
}

// Precise aiming on the level a new player found too coarse: on 1-2 one old keyboard step (1 degree, 2 %) moved the
// landing from one post of the frame to the other.
#include "input/AimController.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike::app
{
namespace
{

sf::Event keyPress(sf::Keyboard::Key code)
{
    sf::Event event{};
    event.type = sf::Event::KeyPressed;
    event.key.code = code;
    return event;
}

TEST(PreciseAim, OnTheLongShotTheKeyboardReachesALandingBetweenThePosts)
{
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-2-the-long-shot.json", Catalog::builtin());
    const GameSession session(level);
    const auto band = session.band();
    ASSERT_TRUE(band);
    const Camera camera = Camera::fromView({-12.8f, 7.2f}, 20.0f, {1280u, 720u});
    // The frame's posts stand at x = 84 and 86 (0.25 m wide): a landing between them is on the roof over the pig
    // between the posts, or on the pig.
    const double inner0 = 84.125;
    const double inner1 = 85.875;
    int between = 0;
    double widestStepM = 0.0;
    double widestFineStepM = 0.0;
    for (int downs = 0; downs <= 30; ++downs) // 45 down to 30 degrees in 0.5 degree steps
    {
        for (int rights = 40; rights <= 50; ++rights) // 90 % to 100 % in 1 % steps, from the default 50 %
        {
            AimController aim; // 45 degrees, 50 %
            for (int i = 0; i < downs; ++i)
                aim.handleEvent(keyPress(sf::Keyboard::Down), camera, {0.0f, 1.5f});
            for (int i = 0; i < rights; ++i)
                aim.handleEvent(keyPress(sf::Keyboard::Right), camera, {0.0f, 1.5f});
            const PredictedFlight flight =
                session.preview(aim.angleDeg(), band->atFraction(aim.powerFraction()).speedMps);
            if (!flight.contact)
                continue;
            const double x = flight.contact->x;
            if (x > inner0 && x < inner1)
                ++between;
            // On open ground (no post or roof in the way) one power step moves the landing by this much.
            const double v0 = band->atFraction(aim.powerFraction()).speedMps;
            const double v1 = band->atFraction(aim.powerFraction() + 0.01).speedMps;
            const double a = aim.angleDeg() * M_PI / 180.0;
            const auto landing = [&](double v)
            {
                const double vy = v * std::sin(a);
                return v * std::cos(a) * (vy + std::sqrt(vy * vy + 2.0 * 9.81 * 1.5)) / 9.81;
            };
            widestStepM = std::max(widestStepM, landing(v1) - landing(v0));
            const double fine = band->atFraction(aim.powerFraction() + 0.002).speedMps; // Alt + an arrow key
            widestFineStepM = std::max(widestFineStepM, landing(fine) - landing(v0));
        }
    }
    EXPECT_GE(between, 3) << "keyboard aims landing between the posts";
    // Near the farthest a full pull throws (93 m), one 1 % power step moves the landing by about the 1.75 m between
    // the posts, so the angle's 0.5 degree steps find the gap; the fine step (Alt) moves it by well under it.
    EXPECT_LT(widestStepM, 2.0);
    EXPECT_GT(widestStepM, 0.0);
    EXPECT_LT(widestFineStepM, 0.4);
}

} // namespace
} // namespace abalike::app

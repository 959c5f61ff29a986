#include "audio/SoundSynth.hpp"
#include "audio/SoundBoard.hpp"

#include <abalike/save/Settings.hpp>
#include <abalike/world/Catalog.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace abalike;
using namespace abalike::app;

namespace
{

constexpr unsigned kRate = 44100;

int peakOf(const std::vector<std::int16_t>& samples)
{
    int peak = 0;
    for (std::int16_t s : samples)
        peak = std::max(peak, std::abs(static_cast<int>(s)));
    return peak;
}

double rmsOf(const std::vector<std::int16_t>& samples)
{
    double sum = 0.0;
    for (std::int16_t s : samples)
        sum += static_cast<double>(s) * s;
    return std::sqrt(sum / static_cast<double>(samples.size()));
}

/// Zero crossings per second: a rough pitch/brightness measure that tells tones apart.
double crossingsPerS(const std::vector<std::int16_t>& samples)
{
    int crossings = 0;
    for (std::size_t i = 1; i < samples.size(); ++i)
        if ((samples[i - 1] < 0) != (samples[i] < 0))
            ++crossings;
    return crossings * static_cast<double>(kRate) / static_cast<double>(samples.size());
}

} // namespace

TEST(SoundSynth, EveryEffectIsShortLoudEnoughAndNeverClips)
{
    for (SoundEffect effect : kAllSoundEffects)
    {
        SCOPED_TRACE(std::string(soundEffectName(effect)));
        const std::vector<std::int16_t> samples = synthesizeSound(effect, kRate);
        const double lengthS = static_cast<double>(samples.size()) / kRate;
        EXPECT_GE(lengthS, 0.05);
        EXPECT_LE(lengthS, 1.5);
        const int peak = peakOf(samples);
        // Normalised to 70 % of full scale: headroom for overlapping voices, no sample at the rails.
        EXPECT_NEAR(peak, 0.7 * 32767, 2.0);
        EXPECT_LT(peak, 32767);
        EXPECT_GT(rmsOf(samples), 0.05 * 32767) << "mostly silence";
        // Both ends fade: no click when a voice starts or stops.
        EXPECT_LT(std::abs(samples.front()), 0.05 * 32767);
        EXPECT_LT(std::abs(samples.back()), 0.05 * 32767);
    }
}

TEST(SoundSynth, SameEffectSameSamplesAndTheRateSetsTheLength)
{
    for (SoundEffect effect : kAllSoundEffects)
    {
        EXPECT_EQ(synthesizeSound(effect, kRate), synthesizeSound(effect, kRate));
        const auto at44 = synthesizeSound(effect, 44100).size();
        const auto at22 = synthesizeSound(effect, 22050).size();
        EXPECT_NEAR(static_cast<double>(at44) / static_cast<double>(at22), 2.0, 0.01);
    }
}

TEST(SoundSynth, EffectsAreDistinct)
{
    std::set<std::vector<std::int16_t>> seen;
    std::set<std::string> names;
    for (SoundEffect effect : kAllSoundEffects)
    {
        seen.insert(synthesizeSound(effect, kRate));
        names.insert(std::string(soundEffectName(effect)));
    }
    EXPECT_EQ(seen.size(), kAllSoundEffects.size());
    EXPECT_EQ(names.size(), kAllSoundEffects.size());
    // Ice rings high, stone thuds low, wood in between: the materials can be told apart by ear.
    const double ice = crossingsPerS(synthesizeSound(SoundEffect::ImpactIce, kRate));
    const double wood = crossingsPerS(synthesizeSound(SoundEffect::ImpactWood, kRate));
    const double stone = crossingsPerS(synthesizeSound(SoundEffect::ImpactStone, kRate));
    EXPECT_GT(ice, 2.0 * wood);
    EXPECT_GT(wood, 1.2 * stone);
    // The win jingle rises and the lose line falls: compare the brightness of their first and last quarters.
    for (auto [effect, rises] : {std::pair{SoundEffect::Win, true}, std::pair{SoundEffect::Lose, false}})
    {
        const auto samples = synthesizeSound(effect, kRate);
        const std::size_t quarter = samples.size() / 4;
        const double first = crossingsPerS({samples.begin(), samples.begin() + quarter});
        const double last = crossingsPerS({samples.end() - quarter, samples.end()});
        EXPECT_EQ(last > first, rises) << soundEffectName(effect);
    }
}

TEST(SoundSynth, MaterialsMapToTheirImpactsByTheirSurface)
{
    const auto impactOf = [](const char* material)
    {
        return impactEffectFor(Catalog::builtin().findMaterial(material)->look.surface);
    };
    EXPECT_EQ(impactOf("ice"), SoundEffect::ImpactIce);
    EXPECT_EQ(impactOf("stone"), SoundEffect::ImpactStone);
    EXPECT_EQ(impactOf("wood"), SoundEffect::ImpactWood);
    EXPECT_EQ(impactOf("tnt"), SoundEffect::ImpactWood);
}

// The silent path: ABALIKE_AUDIO=off turns sound off before OpenAL is touched, and playing is then a no-op.
// (gtest_discover_tests runs each test in its own process, so the once-per-process probe sees this variable.)
TEST(SoundBoard, AudioOffIsSilentAndPlayingIsHarmless)
{
    setenv("ABALIKE_AUDIO", "off", 1);
    SoundBoard board;
    EXPECT_FALSE(board.enabled());
    EXPECT_STREQ(SoundBoard::silentReason(), "ABALIKE_AUDIO=off");
    Settings settings;
    for (SoundEffect effect : kAllSoundEffects)
        board.play(effect, settings, 1.0f);
    settings.mute = true;
    board.play(SoundEffect::Win, settings);
}

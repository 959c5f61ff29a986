#include "audio/SoundSynth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app
{

namespace
{

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kPeak = 0.7; ///< of full scale: headroom when several effects play at once

/// A small deterministic noise source (xorshift32), so the same effect always gives the same samples.
class Noise
{
public:
    explicit Noise(std::uint32_t seed) : m_state(seed) {}
    /// Uniform in [-1, 1].
    double next()
    {
        m_state ^= m_state << 13;
        m_state ^= m_state >> 17;
        m_state ^= m_state << 5;
        return static_cast<double>(m_state) / 2147483647.5 - 1.0;
    }

private:
    std::uint32_t m_state;
};

/// One synthesized voice: a sine sweep plus low-passed noise under an exponential decay.
struct Voice
{
    double startS = 0.0;
    double lengthS = 0.1;
    double fromHz = 440.0;
    double toHz = 440.0;
    double toneLevel = 1.0;
    double noiseLevel = 0.0;
    double noiseSmoothing = 0.0; ///< 0 white noise, towards 1 darker
    double decayPerS = 0.0;      ///< exponential decay rate of the envelope
    double attackS = 0.004;
};

void render(std::vector<double>& out, unsigned rate, const Voice& voice, std::uint32_t seed)
{
    Noise noise(seed);
    double phase = 0.0;
    double smoothed = 0.0;
    const auto first = static_cast<std::size_t>(voice.startS * rate);
    const auto count = static_cast<std::size_t>(voice.lengthS * rate);
    for (std::size_t i = 0; i < count && first + i < out.size(); ++i)
    {
        const double t = static_cast<double>(i) / rate;
        const double along = t / voice.lengthS;
        // Exponential sweep: pitch changes sound even to the ear across octaves.
        const double hz = voice.fromHz * std::pow(voice.toHz / voice.fromHz, along);
        phase += kTwoPi * hz / rate;
        smoothed = voice.noiseSmoothing * smoothed + (1.0 - voice.noiseSmoothing) * noise.next();
        const double attack = std::min(1.0, t / voice.attackS);
        const double release = std::min(1.0, (voice.lengthS - t) / 0.01); // 10 ms fade out: no click at the end
        const double envelope = attack * release * std::exp(-voice.decayPerS * t);
        out[first + i] += envelope * (voice.toneLevel * std::sin(phase) + voice.noiseLevel * smoothed);
    }
}

std::vector<Voice> voicesFor(SoundEffect effect)
{
    switch (effect)
    {
    case SoundEffect::Stretch: // rubber creaking upwards
        return {{0.0, 0.35, 90.0, 180.0, 0.6, 0.4, 0.85, 3.0, 0.05}};
    case SoundEffect::Launch: // a whoosh and a band snap
        return {{0.0, 0.45, 900.0, 300.0, 0.0, 1.0, 0.6, 6.0, 0.02}, {0.0, 0.08, 220.0, 110.0, 1.0, 0.0, 0.0, 30.0}};
    case SoundEffect::ImpactWood: // a hollow knock
        return {{0.0, 0.22, 260.0, 200.0, 1.0, 0.5, 0.7, 25.0}, {0.0, 0.1, 520.0, 480.0, 0.4, 0.0, 0.0, 40.0}};
    case SoundEffect::ImpactIce: // glassy ring: high partials that decay slowly
        return {{0.0, 0.5, 1760.0, 1700.0, 0.6, 0.2, 0.1, 8.0},
                {0.0, 0.5, 2637.0, 2600.0, 0.4, 0.0, 0.0, 10.0},
                {0.0, 0.06, 4000.0, 4000.0, 0.0, 0.8, 0.0, 60.0}};
    case SoundEffect::ImpactStone: // a dull thud
        return {{0.0, 0.3, 110.0, 70.0, 1.0, 0.6, 0.9, 18.0}};
    case SoundEffect::Break: // a crack and a rattle of pieces
        return {{0.0, 0.12, 3000.0, 800.0, 0.0, 1.0, 0.2, 25.0},
                {0.05, 0.5, 400.0, 200.0, 0.2, 0.7, 0.5, 7.0},
                {0.0, 0.15, 150.0, 90.0, 0.8, 0.0, 0.0, 20.0}};
    case SoundEffect::PigDefeated: // a falling squeal and a pop
        return {{0.0, 0.4, 900.0, 300.0, 1.0, 0.1, 0.3, 4.0}, {0.38, 0.1, 200.0, 100.0, 0.6, 0.6, 0.3, 30.0}};
    case SoundEffect::Win: // a rising major arpeggio
        return {{0.0, 0.3, 523.25, 523.25, 1.0, 0.0, 0.0, 4.0},
                {0.15, 0.3, 659.25, 659.25, 1.0, 0.0, 0.0, 4.0},
                {0.3, 0.3, 783.99, 783.99, 1.0, 0.0, 0.0, 4.0},
                {0.45, 0.8, 1046.5, 1046.5, 1.0, 0.0, 0.0, 3.0}};
    case SoundEffect::Lose: // a falling minor line
        return {{0.0, 0.35, 392.0, 392.0, 1.0, 0.0, 0.0, 3.0},
                {0.3, 0.35, 311.13, 311.13, 1.0, 0.0, 0.0, 3.0},
                {0.6, 0.9, 261.63, 220.0, 1.0, 0.0, 0.0, 2.5}};
    }
    return {};
}

} // namespace

std::string_view soundEffectName(SoundEffect effect)
{
    switch (effect)
    {
    case SoundEffect::Stretch:
        return "stretch";
    case SoundEffect::Launch:
        return "launch";
    case SoundEffect::ImpactWood:
        return "impact-wood";
    case SoundEffect::ImpactIce:
        return "impact-ice";
    case SoundEffect::ImpactStone:
        return "impact-stone";
    case SoundEffect::Break:
        return "break";
    case SoundEffect::PigDefeated:
        return "pig-defeated";
    case SoundEffect::Win:
        return "win";
    case SoundEffect::Lose:
        return "lose";
    }
    return "unknown";
}

SoundEffect impactEffectFor(SurfaceKind surface)
{
    switch (surface)
    {
    case SurfaceKind::Frost:
        return SoundEffect::ImpactIce;
    case SurfaceKind::Masonry:
        return SoundEffect::ImpactStone;
    case SurfaceKind::Grain:
    case SurfaceKind::Crate:
        break;
    }
    return SoundEffect::ImpactWood;
}

std::vector<std::int16_t> synthesizeSound(SoundEffect effect, unsigned sampleRateHz)
{
    const std::vector<Voice> voices = voicesFor(effect);
    double lengthS = 0.0;
    for (const Voice& voice : voices)
        lengthS = std::max(lengthS, voice.startS + voice.lengthS);
    lengthS = std::min(lengthS, 1.5);
    std::vector<double> mix(static_cast<std::size_t>(lengthS * sampleRateHz), 0.0);
    std::uint32_t seed = 0x9E3779B9u + static_cast<std::uint32_t>(effect);
    for (const Voice& voice : voices)
        render(mix, sampleRateHz, voice, seed++);

    // Normalise to the same peak, so every effect is as loud as the others and none clips.
    double peak = 0.0;
    for (double sample : mix)
        peak = std::max(peak, std::abs(sample));
    const double gain = peak > 0.0 ? kPeak * 32767.0 / peak : 0.0;
    std::vector<std::int16_t> samples(mix.size());
    for (std::size_t i = 0; i < mix.size(); ++i)
        samples[i] = static_cast<std::int16_t>(std::lround(mix[i] * gain));
    return samples;
}

} // namespace abalike::app

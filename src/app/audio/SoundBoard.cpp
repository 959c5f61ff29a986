#include "audio/SoundBoard.hpp"

#include <AL/alc.h>
#include <abalike/save/Settings.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <string_view>
#include <unistd.h>

namespace abalike::app
{

namespace
{

/// Decides once per process whether there is sound; returns the reason for silence, or null.
const char* probeSilence()
{
    const char* wanted = std::getenv("ABALIKE_AUDIO");
    if (wanted != nullptr && std::string_view(wanted) == "off")
        return "ABALIKE_AUDIO=off";
    // OpenAL Soft logs every backend that fails; quieten it before its first call (overwrite = 0 keeps a level
    // the user asked for).
    setenv("ALSOFT_LOGLEVEL", "0", 0);
    // Open the default device ourselves: SFML would otherwise try, fail, and print errors for every sound. ALSA
    // itself also prints a screenful when there is no sound card, and has no environment switch for it, so
    // stderr points at /dev/null for the length of this one call (start-up, before anything else logs).
    std::fflush(stderr);
    const int savedStderr = dup(STDERR_FILENO);
    const int devNull = open("/dev/null", O_WRONLY);
    if (savedStderr >= 0 && devNull >= 0)
        dup2(devNull, STDERR_FILENO);
    ALCdevice* device = alcOpenDevice(nullptr);
    if (savedStderr >= 0 && devNull >= 0)
        dup2(savedStderr, STDERR_FILENO);
    if (devNull >= 0)
        close(devNull);
    if (savedStderr >= 0)
        close(savedStderr);
    if (device == nullptr)
        return "no audio device";
    alcCloseDevice(device);
    return nullptr;
}

} // namespace

const char* SoundBoard::silentReason()
{
    static const char* const reason = probeSilence();
    return reason == nullptr ? "" : reason;
}

SoundBoard::SoundBoard() : m_enabled(*silentReason() == '\0')
{
    if (!m_enabled)
        return;
    m_voices.resize(kVoices);
    for (SoundEffect effect : kAllSoundEffects)
    {
        const std::vector<std::int16_t> samples = synthesizeSound(effect, kSampleRateHz);
        m_buffers[effect].loadFromSamples(samples.data(), samples.size(), 1, kSampleRateHz);
    }
}

void SoundBoard::play(SoundEffect effect, const Settings& settings, float gain)
{
    if (!m_enabled || settings.mute)
        return;
    const float volume =
        100.0f * static_cast<float>(std::clamp(settings.effectsVolume, 0.0, 1.0)) * std::clamp(gain, 0.0f, 1.0f);
    if (volume <= 0.0f)
        return;
    sf::Sound& voice = m_voices[m_nextVoice];
    m_nextVoice = (m_nextVoice + 1) % m_voices.size();
    voice.stop();
    voice.setBuffer(m_buffers.at(effect));
    voice.setVolume(volume);
    voice.play();
}

} // namespace abalike::app

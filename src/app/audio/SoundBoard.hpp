#pragma once

#include "audio/SoundSynth.hpp"

#include <SFML/Audio/Sound.hpp>
#include <SFML/Audio/SoundBuffer.hpp>
#include <map>
#include <vector>

namespace abalike
{
struct Settings;
}

namespace abalike::app
{

/// Plays the synthesized effects through SFML Audio, or stays silent: with ABALIKE_AUDIO=off, or when OpenAL
/// finds no output device (CI, Xvfb). The device is probed once per process with ALC before SFML touches it,
/// with OpenAL Soft's log quietened (ALSOFT_LOGLEVEL=0 unless the user set it) and ALSA's messages kept off
/// stderr for that one call, so a silent run logs nothing.
class SoundBoard
{
public:
    /// Synthesizes every effect, unless audio is off.
    SoundBoard();

    /// Whether sounds are played at all (false: the silent path).
    bool enabled() const { return m_enabled; }
    /// Why the board is silent ("ABALIKE_AUDIO=off", "no audio device"), empty when enabled.
    static const char* silentReason();

    /// Plays an effect at the settings' effects volume; nothing when muted, silent or the volume is 0.
    /// gain (0..1) scales it further, e.g. by how hard an impact was.
    void play(SoundEffect effect, const Settings& settings, float gain = 1.0f);

private:
    static constexpr unsigned kSampleRateHz = 44100;
    static constexpr std::size_t kVoices = 8; ///< sounds that can overlap; the oldest is cut off first

    bool m_enabled = false;
    std::map<SoundEffect, sf::SoundBuffer> m_buffers;
    /// Made only when enabled: constructing an sf::Sound starts SFML's audio device, which logs when there is none.
    std::vector<sf::Sound> m_voices;
    std::size_t m_nextVoice = 0;
};

} // namespace abalike::app

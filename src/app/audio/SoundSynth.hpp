#pragma once

#include <abalike/world/Looks.hpp>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// The game's sound effects; every one is synthesized at start-up (no sound files).
enum class SoundEffect
{
    Stretch,     ///< the band pulled back
    Launch,      ///< the band released
    ImpactWood,  ///< a hit on wood
    ImpactIce,   ///< a hit on ice
    ImpactStone, ///< a hit on stone
    Break,       ///< a block broke
    PigDefeated, ///< a pig popped
    Win,         ///< level won
    Lose,        ///< level lost
};

/// Every effect, in declaration order.
inline constexpr std::array<SoundEffect, 9> kAllSoundEffects = {
    SoundEffect::Stretch,     SoundEffect::Launch,      SoundEffect::ImpactWood,
    SoundEffect::ImpactIce,   SoundEffect::ImpactStone, SoundEffect::Break,
    SoundEffect::PigDefeated, SoundEffect::Win,         SoundEffect::Lose};

/// A stable name for an effect ("stretch", "impact-wood", ...).
std::string_view soundEffectName(SoundEffect effect);

/// The impact effect for a material's surface: ice rings, stone thuds, wood and crates knock.
SoundEffect impactEffectFor(SurfaceKind surface);

/// Synthesizes an effect as mono 16-bit samples at sampleRateHz: deterministic (same effect, same samples),
/// at most 1.5 s long, peaking at about 70 % of full scale, with a short fade at both ends so it never clicks.
std::vector<std::int16_t> synthesizeSound(SoundEffect effect, unsigned sampleRateHz);

} // namespace abalike::app

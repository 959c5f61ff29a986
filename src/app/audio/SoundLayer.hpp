#pragma once

#include "audio/SoundBoard.hpp"
#include "play/PlayLayer.hpp"

#include <abalike/game/GameSession.hpp>
#include <vector>

namespace abalike::app
{

/// Plays the effects for what happens on the play screen: the band stretched while aiming, the launch, impacts
/// by material (a body losing health), breaks, pigs defeated, win and lose. Reads the session, never changes it.
class SoundLayer : public PlayLayer
{
public:
    std::string_view name() const override { return "sound"; }
    void onLevelStart(PlayView& view) override;
    void afterStep(PlayView& view) override;
    void frameUpdate(PlayView& view, double frameS) override;

private:
    /// Remembers the session's state so that the next step's changes can be told apart.
    void remember(const GameSession& session);

    SoundBoard m_board;
    std::size_t m_shots = 0;
    std::size_t m_seen = 0; ///< events of session.destroyed() already heard
    Phase m_phase = Phase::Aiming;
    std::vector<double> m_health; ///< per entity, the last step's health
    double m_lastSpeedMps = -1.0; ///< the aim's speed last frame; negative: no bird in the slingshot
    double m_sinceStretchS = 1.0;
    double m_sinceImpactS = 1.0;
};

} // namespace abalike::app

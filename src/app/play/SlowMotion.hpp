#pragma once

namespace abalike::app
{

/// Slow motion by taking fewer fixed physics steps per frame: at 1/2 every second fixed tick steps the world, at 1/4
/// every fourth. The physics itself is unchanged (same step, same results); only the pace at which it is shown.
class SlowMotion
{
public:
    /// 1 (real time), 2 (half speed) or 4 (quarter speed).
    int divisor() const { return m_divisor; }
    /// Real time -> 1/2 -> 1/4 -> real time.
    void cycle()
    {
        m_divisor = m_divisor >= 4 ? 1 : m_divisor * 2;
        m_tick = 0;
    }
    /// Called once per fixed tick: whether this tick takes a physics step.
    bool takeStep()
    {
        if (++m_tick < m_divisor)
            return false;
        m_tick = 0;
        return true;
    }
    /// "1x", "1/2x", "1/4x" in the game's typography.
    const char* label() const { return m_divisor == 1 ? "1\u00D7" : m_divisor == 2 ? "\u00BD\u00D7" : "\u00BC\u00D7"; }

private:
    int m_divisor = 1;
    int m_tick = 0;
};

} // namespace abalike::app

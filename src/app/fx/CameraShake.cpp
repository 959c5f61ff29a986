#include "fx/CameraShake.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

void CameraShake::kick(float amplitudePx)
{
    m_amplitudePx = std::min(m_amplitudePx + std::max(amplitudePx, 0.0f), kMaxPx);
}

void CameraShake::update(double frameS)
{
    if (m_amplitudePx <= 0.0f)
        return;
    m_timeS += frameS;
    m_amplitudePx *= static_cast<float>(std::exp(-frameS / kDecayS));
    if (m_amplitudePx < kStillPx)
        reset();
}

void CameraShake::reset()
{
    m_amplitudePx = 0.0f;
    m_timeS = 0.0;
}

sf::Vector2f CameraShake::offsetPx() const
{
    if (m_amplitudePx <= 0.0f)
        return {0.0f, 0.0f};
    // Incommensurate frequencies (Hz) so the shake does not trace a visible loop.
    const double t = m_timeS;
    const double x = 0.7 * std::sin(2.0 * 3.14159265 * 23.0 * t) + 0.3 * std::sin(2.0 * 3.14159265 * 37.0 * t + 1.3);
    const double y = 0.6 * std::sin(2.0 * 3.14159265 * 29.0 * t + 0.7) + 0.4 * std::sin(2.0 * 3.14159265 * 41.0 * t);
    return {m_amplitudePx * static_cast<float>(x), m_amplitudePx * static_cast<float>(y)};
}

} // namespace abalike::app

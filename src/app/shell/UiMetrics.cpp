#include "shell/UiMetrics.hpp"

#include "render/Hud.hpp"
#include "shell/PlayerSettings.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

float UiMetrics::scale() const
{
    return hudScale(m_window.getSize()) * static_cast<float>(m_settings.current().textScale);
}

unsigned UiMetrics::textSize(float nominal) const
{
    return static_cast<unsigned>(std::max(9.0f, std::round(nominal * scale())));
}

} // namespace abalike::app

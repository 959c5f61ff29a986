#include "shell/RunControl.hpp"

namespace abalike::app
{

std::vector<ScriptedShot> RunControl::takeScriptedShots()
{
    if (m_shotsTaken)
        return {};
    m_shotsTaken = true;
    return m_options.shots;
}

void RunControl::startFrame()
{
    m_frameTimes = FrameTimes{};
    ++m_frame;
}

} // namespace abalike::app

#include "shell/Navigator.hpp"

#include <utility>

namespace abalike::app
{

void Navigator::quit(int exitCode)
{
    if (!m_exitCode)
        m_exitCode = exitCode;
}

std::vector<sf::Event> Navigator::takePosted()
{
    return std::exchange(m_posted, {});
}

} // namespace abalike::app

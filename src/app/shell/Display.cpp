#include "shell/Display.hpp"

#include <cstdlib>
#include <iostream>

namespace abalike::app
{

bool haveDisplay()
{
#if defined(__unix__) && !defined(__APPLE__)
    if (std::getenv("DISPLAY") == nullptr)
    {
        std::cerr << "abalike: no display (DISPLAY is not set); for offline frames run under xvfb-run\n";
        return false;
    }
#endif
    return true;
}

} // namespace abalike::app

#pragma once

namespace abalike::app
{

/// SFML aborts the process when it cannot reach an X server; false (with one line on stderr) when there is none.
bool haveDisplay();

} // namespace abalike::app

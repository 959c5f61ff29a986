#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <string>
#include <vector>

namespace abalike
{
class SaveStore;
}

namespace abalike::app
{

class Trace;
class UiMetrics;

/// One-line messages for the player, shown for a few seconds over every screen, printed on stderr and traced.
class Notices
{
public:
    explicit Notices(Trace& trace) : m_trace(trace) {}

    /// A message that stands on its own.
    void notify(const std::string& message);
    /// A notice about one setting (topic: "speed", "overlay", ...): it replaces that setting's earlier notice, so
    /// pressing a key twice never shows "Speed 1/2x" and "Speed 1/4x" at once.
    void notify(const std::string& message, const std::string& topic);
    /// Shows what the player's files had to say (a damaged save, a folder that cannot be written).
    void takeMessagesOf(SaveStore& store);

    /// Ages the notices by a frame's time and drops those shown long enough.
    void age(double frameS);
    /// Draws them centred above the level's hint, each wrapped to the window.
    void draw(sf::RenderTarget& target, const UiMetrics& ui) const;

private:
    struct Notice
    {
        std::string text;
        double shownS = 0.0;
        std::string topic; ///< empty: stands on its own
    };

    Trace& m_trace;
    std::vector<Notice> m_notices;
};

} // namespace abalike::app

#pragma once

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace abalike::app
{

/// `abalike play --trace FILE`: one JSON object per line for each thing the game did (screen changes, levels
/// started, launches, results, settings changed), with the frame it happened in. Tests read it to check flows
/// that a screenshot cannot show. Writes nothing when no file was asked for.
class Trace
{
public:
    Trace() = default;
    /// Opens the file; false when it cannot be written.
    bool open(const std::string& path);
    bool active() const { return m_out.is_open(); }

    void setFrame(long long frame) { m_frame = frame; }
    /// Writes {"frame": N, "event": EVENT, ...fields}.
    void write(const std::string& event, const nlohmann::json& fields = nlohmann::json::object());

private:
    std::ofstream m_out;
    long long m_frame = 0;
};

} // namespace abalike::app

#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace abalike::app
{

/// A one-line progress bar on stderr, drawn only when stderr is a terminal (never in pipes, logs or tests).
class ProgressBar
{
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Redraws at most ten times a second.
    void update(std::size_t done, std::size_t total);
    /// Clears the line.
    void finish();

private:
    std::string m_label;
    bool m_enabled = false;
    bool m_drawn = false;
    std::chrono::steady_clock::time_point m_lastDraw{};
};

} // namespace abalike::app

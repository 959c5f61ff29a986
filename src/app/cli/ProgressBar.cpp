#include "cli/ProgressBar.hpp"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace abalike::app
{

namespace
{
constexpr int kWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
} // namespace

ProgressBar::ProgressBar(std::string label) : m_label(std::move(label)), m_enabled(::isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar()
{
    finish();
}

void ProgressBar::update(std::size_t done, std::size_t total)
{
    if (!m_enabled || total == 0)
        return;
    const auto now = std::chrono::steady_clock::now();
    if (m_drawn && now - m_lastDraw < kRedrawInterval && done < total)
        return;
    m_lastDraw = now;
    m_drawn = true;
    const double share = std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
    const int filled = static_cast<int>(share * kWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %3d%% %zu/%zu", m_label.c_str(), bar.c_str(), static_cast<int>(share * 100.0), done,
                 total);
    std::fflush(stderr);
}

void ProgressBar::finish()
{
    if (!m_drawn)
        return;
    m_drawn = false;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

} // namespace abalike::app

#include "render/FontMetrics.hpp"

#include <memory>
#include <vector>

namespace abalike::app
{

FontMetrics::FontMetrics(const sf::Font& font) : m_font(&font), m_family(font.getInfo().family) {}

FontMetrics& FontMetrics::of(const sf::Font& font)
{
    thread_local std::vector<std::unique_ptr<FontMetrics>> fonts;
    for (std::unique_ptr<FontMetrics>& metrics : fonts)
        if (metrics->m_font == &font)
        {
            if (metrics->m_family != font.getInfo().family)
                metrics.reset(new FontMetrics(font));
            return *metrics;
        }
    fonts.push_back(std::unique_ptr<FontMetrics>(new FontMetrics(font)));
    return *fonts.back();
}

float FontMetrics::kerning(sf::Uint32 first, sf::Uint32 second, unsigned size)
{
    if (first == 0 || second == 0)
        return 0.0f;
    // Code points take 21 bits each.
    const std::uint64_t key = (static_cast<std::uint64_t>(size) << 42) | (static_cast<std::uint64_t>(first) << 21) |
                              static_cast<std::uint64_t>(second);
    const auto [entry, added] = m_kerning.try_emplace(key, 0.0f);
    if (added)
        entry->second = m_font->getKerning(first, second, size);
    return entry->second;
}

float FontMetrics::lineSpacing(unsigned size)
{
    const auto [entry, added] = m_lineSpacing.try_emplace(size, 0.0f);
    if (added)
        entry->second = m_font->getLineSpacing(size);
    return entry->second;
}

} // namespace abalike::app

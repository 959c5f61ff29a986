#pragma once

#include <SFML/Graphics/Font.hpp>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace abalike::app
{

/// A font's kerning and line spacing at each size, remembered. sf::Font asks FreeType for them on every call and
/// switches FreeType's character size whenever a call's size differs from the last one's, so laying out a frame's
/// labels in their several sizes spent about a millisecond of each frame in FreeType (perf on `bench frames`).
class FontMetrics
{
public:
    /// The metrics of this font, kept for the thread; a font object with another family at the same address starts
    /// afresh.
    static FontMetrics& of(const sf::Font& font);

    float kerning(sf::Uint32 first, sf::Uint32 second, unsigned size);
    float lineSpacing(unsigned size);

    /// The width of a line at this size, laid out by `measure` the first time it is asked for and remembered: the
    /// panels measure the same lines every frame, and wrapping a paragraph measures each line once per word in it,
    /// while laying a line out costs a kerning and a glyph look-up per character.
    template <class Measure>
    float width(const sf::String& text, unsigned size, Measure&& measure)
    {
        std::u32string key(1, static_cast<char32_t>(size));
        key.append(text.begin(), text.end());
        if (const auto found = m_widths.find(key); found != m_widths.end())
            return found->second;
        // Live numbers make new lines every frame: start afresh now and then rather than grow without end.
        if (m_widths.size() >= kMaxWidths)
            m_widths.clear();
        return m_widths.emplace(std::move(key), measure()).first->second;
    }

private:
    explicit FontMetrics(const sf::Font& font);

    const sf::Font* m_font;
    std::string m_family;
    std::unordered_map<std::uint64_t, float> m_kerning;
    std::unordered_map<unsigned, float> m_lineSpacing;
    static constexpr std::size_t kMaxWidths = 8192;
    std::unordered_map<std::u32string, float> m_widths; ///< keyed by the size, then the line's characters
};

} // namespace abalike::app

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

private:
    explicit FontMetrics(const sf::Font& font);

    const sf::Font* m_font;
    std::string m_family;
    std::unordered_map<std::uint64_t, float> m_kerning;
    std::unordered_map<unsigned, float> m_lineSpacing;
};

} // namespace abalike::app

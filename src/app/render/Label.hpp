#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/System/String.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// Which point of a label its position names.
enum class Align
{
    Left,
    Centre,
    Right,
};

/// UTF-8 text (degree signs, arrows) as an SFML string.
sf::String utf8(std::string_view text);

/// Size of a line of text without drawing it.
sf::Vector2f measureText(const sf::Font& font, const sf::String& text, unsigned size);

/// Breaks UTF-8 text into lines no wider than maxWidth at spaces (a single word wider than that gets a line of its
/// own).
std::vector<std::string> wrapText(const sf::Font& font, std::string_view text, unsigned size, float maxWidth);

/// The text's first whole sentences (ending in ". ", "? " or "! ") that wrap into at most maxLines lines, wrapped;
/// empty when not even the first sentence does. A card short of room says less rather than stop mid-sentence.
std::vector<std::string> wrapWholeSentences(const sf::Font& font, std::string_view text, unsigned size, float maxWidth,
                                            std::size_t maxLines);

/// Where fitToWidth may cut a line that is too wide.
enum class Cut
{
    AtWord,      ///< at a space: a sentence keeps whole words
    AtCharacter, ///< between any two characters (never inside a UTF-8 sequence): a title keeps as much as it can
};

/// The UTF-8 text whole when it fits maxWidth, else its longest start that fits with an ellipsis after it. With nothing
/// that fits, empty (AtWord: not even the first word) or the ellipsis alone (AtCharacter).
std::string fitToWidth(const sf::Font& font, std::string_view text, unsigned size, float maxWidth, Cut cut);

/// What a text is for. The trace records each text of a frame with its kind, so a test can check that the game mode
/// shows no physics sentence or formula while the learn mode does.
enum class TextKind
{
    Interface, ///< menus, buttons, notices
    Hud,       ///< level, score, birds, pigs, the aim
    Hint,      ///< the level's hint, a lesson's step
    Physics,   ///< a sentence or panel of physics with its numbers
    Formula,   ///< a formula (F = k x, E = 1/2 F x, ...)
};

/// The kind's name in the trace ("interface", "hud", "hint", "physics", "formula").
const char* textKindName(TextKind kind);

/// Marks every text drawn while it lives as one kind; scopes nest, the innermost wins.
class TextKindScope
{
public:
    explicit TextKindScope(TextKind kind);
    ~TextKindScope();
    TextKindScope(const TextKindScope&) = delete;
    TextKindScope& operator=(const TextKindScope&) = delete;

private:
    TextKind m_previous;
};

/// A text as one frame drew it.
struct DrawnText
{
    std::string text;
    TextKind kind = TextKind::Interface;
};

/// While set, every text drawLabel draws is also appended here (the trace's record of what one frame shows).
void setDrawnTextSink(std::vector<DrawnText>* sink);

/// Draws one line of text with a soft shadow; `position` is the top of the line at the aligned point.
/// Returns the bounds it covers.

sf::FloatRect drawLabel(sf::RenderTarget& target, const sf::Font& font, const sf::String& text, sf::Vector2f position,
                        unsigned size, sf::Color colour, Align align = Align::Left);

} // namespace abalike::app

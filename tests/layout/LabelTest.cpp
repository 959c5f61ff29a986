// Needs a display (a font makes its glyph textures): it runs with the layout walk under a virtual display.
#include "render/Label.hpp"
#include "render/Font.hpp"

#include <SFML/Graphics/Font.hpp>
#include <gtest/gtest.h>
#include <memory>

namespace abalike::app
{
namespace
{

const sf::Font& labelFont()
{
    static const std::unique_ptr<sf::Font> loaded = loadGameFont();
    return *loaded;
}

std::string joinedLines(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& line : lines)
        text += (text.empty() ? "" : " ") + line;
    return text;
}

TEST(Label, ACardShortOfRoomKeepsWholeSentencesOnly)
{
    const sf::Font& font = labelFont();
    const std::string text = "Press G. The chart shows how far this bird lands at every angle, at the pull you have "
                             "now. Is 45 degrees the best? Not from a height!";
    const float width = measureText(font, utf8("The chart shows how far this bird"), 16).x;
    const std::vector<std::string> all = wrapText(font, text, 16, width);
    ASSERT_GT(all.size(), 4u);
    // Room for everything: everything, wrapped as wrapText does.
    EXPECT_EQ(wrapWholeSentences(font, text, 16, width, all.size()), all);
    // One line short: the last sentence goes whole, never a part of it.
    EXPECT_EQ(joinedLines(wrapWholeSentences(font, text, 16, width, all.size() - 1)),
              "Press G. The chart shows how far this bird lands at every angle, at the pull you have now. Is 45 "
              "degrees the best?");
    // One line: the first sentence only; no line: nothing.
    EXPECT_EQ(joinedLines(wrapWholeSentences(font, text, 16, width, 1)), "Press G.");
    EXPECT_TRUE(wrapWholeSentences(font, text, 16, width, 0).empty());
    // Decimal points are not sentence ends.
    EXPECT_EQ(joinedLines(wrapWholeSentences(font, "g = 1.62 m/s\u00B2 here. More.", 16, 1000.0f, 1)),
              "g = 1.62 m/s\u00B2 here. More.");
}

} // namespace
} // namespace abalike::app

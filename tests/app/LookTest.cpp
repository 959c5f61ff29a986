// WCAG 2.1 contrast of every UI text on everything it is drawn on, in every look: at least 4.5:1 (AA) in the
// standard and colour-blind-safe looks, at least 7:1 in high contrast. Translucent layers are composited over the
// worst backdrop they can sit on (a white cloud under a panel).
#include "render/Look.hpp"

#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

namespace
{
double worstContrast(const Look& look, std::string* where)
{
    double worst = 100.0;
    for (const TextOnBackground& pair : uiTextPairs(look))
    {
        sf::Color background = pair.layers.front();
        for (std::size_t i = 1; i < pair.layers.size(); ++i)
            background = composite(pair.layers[i], background);
        const double ratio = contrastRatio(composite(pair.text, background), background);
        if (ratio < worst)
        {
            worst = ratio;
            *where = pair.what;
        }
    }
    return worst;
}
} // namespace

TEST(Contrast, TheWcagFormulaGivesItsKnownValues)
{
    EXPECT_NEAR(contrastRatio({0, 0, 0}, {255, 255, 255}), 21.0, 1e-9);
    EXPECT_NEAR(contrastRatio({255, 255, 255}, {255, 255, 255}), 1.0, 1e-9);
    EXPECT_NEAR(contrastRatio({118, 118, 118}, {255, 255, 255}), 4.54, 0.01); // the classic AA grey on white
    EXPECT_EQ(composite({255, 255, 255, 0}, {10, 20, 30}), sf::Color(10, 20, 30));
    EXPECT_EQ(composite({255, 255, 255, 255}, {10, 20, 30}), sf::Color(255, 255, 255));
    EXPECT_EQ(composite({0, 0, 0, 128}, {255, 255, 255}), sf::Color(127, 127, 127));
}

TEST(Contrast, EveryUiTextMeetsAaInTheStandardAndColourBlindLooksAndSevenToOneInHighContrast)
{
    for (const Palette palette : {Palette::Standard, Palette::ColourBlindSafe})
    {
        std::string where;
        EXPECT_GE(worstContrast(lookFor(palette, false), &where), 4.5) << paletteName(palette) << ": " << where;
        EXPECT_GE(worstContrast(lookFor(palette, true), &where), 7.0) << paletteName(palette) << " high: " << where;
    }
}

TEST(Contrast, TheCheckCanFail)
{
    // Grey text on a half-transparent panel over a white cloud: the check must catch it.
    Look look = lookFor(Palette::Standard, false);
    look.textDim = {120, 120, 130};
    look.panel.a = 120;
    std::string where;
    EXPECT_LT(worstContrast(look, &where), 4.5);
}

TEST(Looks, TheSettingsChooseTheLook)
{
    EXPECT_FALSE(lookFor(Palette::Standard, false).colourBlindSafe);
    EXPECT_TRUE(lookFor(Palette::ColourBlindSafe, false).colourBlindSafe);
    EXPECT_TRUE(lookFor(Palette::Standard, true).highContrast);
    // High contrast draws its panels and cards opaque.
    EXPECT_EQ(lookFor(Palette::ColourBlindSafe, true).card.a, 255);
    EXPECT_GE(lookFor(Palette::Standard, true).panel.a, 250);
    // The flown path and its contact are told apart from the preview without red against green.
    const Look safe = lookFor(Palette::ColourBlindSafe, false);
    EXPECT_NE(safe.actualContact, lookFor(Palette::Standard, false).actualContact);
}

#pragma once

#include <SFML/Graphics/Color.hpp>
#include <abalike/save/Settings.hpp>
#include <string>
#include <vector>

namespace abalike::app
{

/// The colours that change with the player's accessibility settings: every UI text and what it sits on, the flown
/// and predicted paths, and how strongly materials are told apart by pattern. The scene's own colours (sky, grass,
/// characters) stay in palette::. Palette.hpp's names for these (palette::kText, ...) read the active look.
struct Look
{
    sf::Color text;
    sf::Color textDim;
    sf::Color textDisabled;
    sf::Color star; ///< headings, the score, stars
    sf::Color starEmpty;
    sf::Color panel; ///< HUD panels and labels over the scene
    sf::Color card;  ///< menus' and results' cards
    sf::Color button;
    sf::Color buttonSelected;
    sf::Color buttonOutline;
    sf::Color tileLocked;
    sf::Color scrim; ///< darkens the scene under a menu
    sf::Color teachPanel;
    sf::Color teachPanelEdge;
    sf::Color menuTop; ///< the menus' backdrop gradient
    sf::Color menuBottom;
    sf::Color actualPath;
    sf::Color actualContact;
    sf::Color previewDot;
    sf::Color previewOutline;
    bool colourBlindSafe = false; ///< materials in the Okabe-Ito set, told apart by strong patterns too
    bool highContrast = false;
};

/// The look for these settings: standard, colour-blind safe, and either with high contrast.
Look lookFor(Palette palette, bool highContrast);

/// The look everything is drawn with now.
const Look& activeLook();
/// Switches the look (the app does, when the settings change).
void setActiveLook(const Look& look);

/// One pair of UI text and what it is drawn on, for the contrast check: the layers under the text from the bottom
/// up; the bottom one is opaque and the worst thing the layers above can sit on (a white cloud under a translucent
/// panel).
struct TextOnBackground
{
    std::string what;
    sf::Color text;
    std::vector<sf::Color> layers;
};

/// Every UI text colour on every background it is drawn on, in this look.
std::vector<TextOnBackground> uiTextPairs(const Look& look);

/// WCAG 2.1 contrast ratio of two opaque colours (1 to 21).
double contrastRatio(sf::Color a, sf::Color b);
/// A colour drawn over an opaque one with its alpha (the result is opaque).
sf::Color composite(sf::Color over, sf::Color under);

} // namespace abalike::app

#include "render/Look.hpp"

#include <cmath>

namespace abalike::app
{

namespace
{
const sf::Color kWhiteCloud(255, 255, 255); ///< the brightest thing behind a translucent panel
const sf::Color kDarkGround(98, 66, 40);    ///< the darkest (kEarthDark)
const sf::Color kSkyBottom(196, 228, 248);

Look standardLook()
{
    Look look;
    look.text = {255, 255, 255};
    look.textDim = {200, 210, 225};
    look.textDisabled = {160, 168, 182};
    look.star = {255, 206, 40};
    look.starEmpty = {70, 78, 96};
    look.panel = {20, 28, 44, 205};
    look.card = {24, 34, 56, 240};
    look.button = {30, 42, 68, 235};
    look.buttonSelected = {48, 74, 124, 245};
    look.buttonOutline = {120, 140, 176};
    look.tileLocked = {40, 44, 54, 235};
    look.scrim = {8, 12, 22, 185};
    look.teachPanel = {14, 20, 34, 215};
    look.teachPanelEdge = {110, 130, 170, 200};
    look.menuTop = {22, 38, 70};
    look.menuBottom = {40, 74, 118};
    look.actualPath = {255, 140, 0};
    look.actualContact = {220, 40, 30};
    look.previewDot = {255, 255, 255};
    look.previewOutline = {30, 34, 48};
    return look;
}

Look& mutableLook()
{
    static Look active = standardLook();
    return active;
}

double channel(sf::Uint8 value)
{
    const double c = value / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double luminance(sf::Color c)
{
    return 0.2126 * channel(c.r) + 0.7152 * channel(c.g) + 0.0722 * channel(c.b);
}
} // namespace

Look lookFor(Palette palette, bool highContrast)
{
    Look look = standardLook();
    if (palette == Palette::ColourBlindSafe)
    {
        // Okabe and Ito's set: the flown path orange, its contact vermilion against the preview's blue-white.
        look.colourBlindSafe = true;
        look.actualPath = {230, 159, 0};
        look.actualContact = {213, 94, 0};
        look.previewOutline = {0, 60, 110};
    }
    if (highContrast)
    {
        look.highContrast = true;
        look.textDim = {235, 240, 248};
        look.textDisabled = {200, 206, 216};
        look.panel = {6, 8, 14, 250};
        look.card = {6, 8, 14, 255};
        look.button = {10, 14, 24, 255};
        look.buttonSelected = {0, 56, 130, 255};
        look.buttonOutline = {255, 255, 255};
        look.tileLocked = {24, 24, 28, 255};
        look.scrim = {0, 0, 0, 225};
        look.teachPanel = {4, 6, 12, 250};
        look.teachPanelEdge = {255, 255, 255, 255};
        look.menuTop = {4, 10, 24};
        look.menuBottom = {10, 22, 44};
        look.starEmpty = {120, 126, 140};
        look.previewOutline = {0, 0, 0};
    }
    return look;
}

const Look& activeLook()
{
    return mutableLook();
}

void setActiveLook(const Look& look)
{
    mutableLook() = look;
}

std::vector<TextOnBackground> uiTextPairs(const Look& look)
{
    std::vector<TextOnBackground> pairs;
    const auto add = [&pairs](std::string what, sf::Color text, std::vector<sf::Color> layers)
    {
        pairs.push_back({std::move(what), text, std::move(layers)});
    };
    // HUD panels, labels, the toolbar's tooltip and notices: over anything in the scene, a white cloud the worst.
    for (const sf::Color text : {look.text, look.textDim, look.star})
        add("HUD panel", text, {kWhiteCloud, look.panel});
    // The teaching overlay's panels, arrow labels and feedback.
    for (const sf::Color text : {look.text, look.textDim, look.star})
        add("teaching panel", text, {kWhiteCloud, look.teachPanel});
    // Cards (menus, results, help, settings) over the dimmed scene.
    for (const sf::Color text : {look.text, look.textDim, look.star})
        add("card", text, {kWhiteCloud, look.scrim, look.card});
    // Buttons: menus over the scrim, the toolbar straight over the sky.
    for (const sf::Color under : {kWhiteCloud, kSkyBottom})
    {
        add("button", look.text, {under, look.scrim, look.button});
        add("selected button", look.text, {under, look.scrim, look.buttonSelected});
        add("disabled button", look.textDisabled, {under, look.scrim, look.button});
        add("toolbar button", look.text, {under, look.button});
    }
    // Text straight on the scrim: the title, its subtitle and hint.
    for (const sf::Color text : {look.text, look.star})
        add("title over the scrim", text, {kWhiteCloud, look.scrim});
    // Level and lesson select: the backdrop gradient and the tiles.
    for (const sf::Color backdrop : {look.menuTop, look.menuBottom})
        for (const sf::Color text : {look.text, look.textDim, look.star})
            add("menu backdrop", text, {backdrop});
    add("locked tile", look.textDisabled, {look.menuBottom, look.tileLocked});
    add("tile", look.text, {look.menuBottom, look.button});
    add("selected tile", look.text, {look.menuBottom, look.buttonSelected});
    // The play screen's hint lines, over the ground band at the bottom.
    for (const sf::Color text : {look.text, look.textDim})
        add("hint over the ground", text, {kDarkGround});
    // Score pop-ups: outlined text; the outline is what it is read against.
    add("score pop-up", look.text, {sf::Color(30, 24, 16)});
    add("pig pop-up", look.star, {sf::Color(30, 24, 16)});
    return pairs;
}

double contrastRatio(sf::Color a, sf::Color b)
{
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

sf::Color composite(sf::Color over, sf::Color under)
{
    const double alpha = over.a / 255.0;
    const auto mix = [alpha](sf::Uint8 top, sf::Uint8 bottom)
    {
        return static_cast<sf::Uint8>(std::lround(alpha * top + (1.0 - alpha) * bottom));
    };
    return {mix(over.r, under.r), mix(over.g, under.g), mix(over.b, under.b), 255};
}

} // namespace abalike::app

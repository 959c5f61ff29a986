#pragma once

#include "render/Look.hpp"

#include <SFML/Graphics/Color.hpp>
#include <abalike/world/Looks.hpp>

namespace abalike::app
{

/// Colours of a building material.
struct MaterialColours
{
    sf::Color fill;
    sf::Color outline;
    sf::Color detail;    ///< wood grain, stone speckles
    sf::Color highlight; ///< ice glint, stone chips
};

/// Colours of a bird type.
struct BirdColours
{
    sf::Color body;
    sf::Color outline;
    sf::Color belly;
    sf::Color brow;
};

/// Named colours of the scene; everything is drawn from these, no image files. The UI's colours and the paths'
/// are references into the active look (render/Look.hpp), so they follow the accessibility settings.
namespace palette
{
inline const sf::Color kSkyTop(92, 160, 228);
inline const sf::Color kSkyBottom(196, 228, 248);
inline const sf::Color kCloud(255, 255, 255, 215);
inline const sf::Color kGrass(96, 178, 64);
inline const sf::Color kGrassDark(64, 140, 44);
inline const sf::Color kEarth(122, 84, 52);
inline const sf::Color kEarthDark(98, 66, 40);
inline const sf::Color kTerrain(88, 62, 42);
inline const sf::Color kTerrainEdge(62, 42, 28);
inline const sf::Color kSlingshotWood(112, 70, 34);
inline const sf::Color kSlingshotDark(78, 46, 20);
inline const sf::Color kBand(58, 28, 18);
inline const sf::Color kCrack(45, 30, 20, 220);

inline const sf::Color kPig(124, 204, 64);
inline const sf::Color kPigOutline(58, 120, 30);
inline const sf::Color kPigSnout(168, 228, 110);
inline const sf::Color kPigNostril(48, 96, 24);
inline const sf::Color kBruise(110, 70, 120, 150);
inline const sf::Color kHelmet(150, 152, 162);
inline const sf::Color kHelmetDark(96, 98, 108);
inline const sf::Color kEyeWhite(255, 255, 255);
inline const sf::Color kPupil(20, 20, 24);
inline const sf::Color kBeak(250, 160, 30);
inline const sf::Color kBeakDark(214, 120, 20);
inline const sf::Color kEgg(250, 244, 226);
inline const sf::Color kEggOutline(178, 166, 140);
inline const sf::Color kAbility(255, 230, 60);

inline const sf::Color& kPreviewDot = activeLook().previewDot;
inline const sf::Color& kPreviewOutline = activeLook().previewOutline;
inline const sf::Color& kActualPath = activeLook().actualPath;
inline const sf::Color& kActualContact = activeLook().actualContact;
inline const sf::Color kTrailPuff(255, 255, 255); ///< earlier shots' paths, drawn faded
inline const sf::Color kTrailRim(60, 66, 84);
inline const sf::Color& kPanel = activeLook().panel;
inline const sf::Color& kText = activeLook().text;
inline const sf::Color& kTextDim = activeLook().textDim;
inline const sf::Color& kStar = activeLook().star;
inline const sf::Color& kStarEmpty = activeLook().starEmpty;
inline const sf::Color& kCard = activeLook().card;
inline const sf::Color& kMenuTop = activeLook().menuTop;
inline const sf::Color& kMenuBottom = activeLook().menuBottom;
inline const sf::Color& kButton = activeLook().button;
inline const sf::Color& kButtonSelected = activeLook().buttonSelected;
inline const sf::Color& kButtonOutline = activeLook().buttonOutline;
inline const sf::Color& kTileLocked = activeLook().tileLocked;
inline const sf::Color& kTextDisabled = activeLook().textDisabled;
inline const sf::Color& kScrim = activeLook().scrim;
} // namespace palette

/// A catalog colour as SFML's.
sf::Color colourOf(const Rgba& rgba);

/// A material's colours, from its look in the catalog.
MaterialColours materialColours(const MaterialLook& look);

/// A bird's colours, from its look in the catalog.
BirdColours birdColours(const BirdLook& look);

/// The colour scaled towards black by `factor` (1 keeps it, 0 is black); alpha kept.
sf::Color darken(sf::Color colour, float factor);

/// The colour with its alpha multiplied by `factor` (0..1).
sf::Color faded(sf::Color colour, float factor);

} // namespace abalike::app

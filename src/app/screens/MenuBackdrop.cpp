#include "screens/MenuBackdrop.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>

namespace abalike::app
{

float drawMenuBackdrop(sf::RenderTarget& target, AppContext& app, const std::string& title, const std::string& subtitle,
                       float top)
{
    sf::RectangleShape back(sf::Vector2f(target.getSize()));
    back.setFillColor(palette::kMenuTop);
    target.draw(back);
    const sf::Vector2f window(target.getSize());
    const float centre = 0.5f * window.x;
    float y = top * window.y;
    const sf::Font* font = app.ui().font();
    if (font == nullptr)
        return y;
    const unsigned titleSize = app.ui().textSize(44.0f);
    drawLabel(target, *font, utf8(title), {centre, y}, titleSize, palette::kStar, Align::Centre);
    y += font->getLineSpacing(titleSize);
    const unsigned subtitleSize = app.ui().textSize(18.0f);
    drawLabel(target, *font, utf8(subtitle), {centre, y}, subtitleSize, palette::kTextDim, Align::Centre);
    return y + font->getLineSpacing(subtitleSize) + 16.0f * app.ui().scale();
}

} // namespace abalike::app

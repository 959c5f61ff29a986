#include "render/CameraControls.hpp"

#include <cmath>

namespace abalike::app
{

namespace
{
sf::Vector2f middleOf(const CameraRig& rig)
{
    const sf::Vector2u size = rig.camera().windowSize();
    return {0.5f * static_cast<float>(size.x), 0.5f * static_cast<float>(size.y)};
}
} // namespace

bool CameraControls::handleEvent(const sf::Event& event, CameraRig& rig, bool leftIsFree)
{
    switch (event.type)
    {
    case sf::Event::MouseWheelScrolled:
        if (event.mouseWheelScroll.delta == 0.0f)
            return false;
        rig.zoomAt(std::pow(kWheelZoom, event.mouseWheelScroll.delta),
                   {static_cast<float>(event.mouseWheelScroll.x), static_cast<float>(event.mouseWheelScroll.y)});
        return true;
    case sf::Event::MouseButtonPressed:
    {
        const bool middle = event.mouseButton.button == sf::Mouse::Middle;
        if (!middle && !(event.mouseButton.button == sf::Mouse::Left && leftIsFree))
            return false;
        m_dragFrom = sf::Vector2f(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
        m_dragMoved = false;
        return true;
    }
    case sf::Event::MouseMoved:
    {
        if (!m_dragFrom)
            return false;
        const sf::Vector2f at(static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y));
        const sf::Vector2f delta = at - *m_dragFrom;
        // A hand's tremor on a click is not a pan: the view stays where it was until the drag is deliberate.
        if (!m_dragMoved && std::hypot(delta.x, delta.y) < kDragStartPx)
            return true;
        m_dragMoved = true;
        rig.panPixels(delta);
        m_dragFrom = at;
        return true;
    }
    case sf::Event::MouseButtonReleased:
        if (!m_dragFrom ||
            (event.mouseButton.button != sf::Mouse::Left && event.mouseButton.button != sf::Mouse::Middle))
            return false;
        m_dragFrom.reset();
        return true;
    case sf::Event::KeyPressed:
    {
        if (event.key.control || event.key.alt)
            return false;
        const float step = kKeyPanPx * (event.key.shift ? 4.0f : 1.0f);
        switch (event.key.code)
        {
        case sf::Keyboard::Add:
        case sf::Keyboard::Equal:
            rig.zoomAt(kKeyZoom, middleOf(rig));
            return true;
        case sf::Keyboard::Subtract:
        case sf::Keyboard::Hyphen:
            rig.zoomAt(1.0f / kKeyZoom, middleOf(rig));
            return true;
        case sf::Keyboard::Home:
        case sf::Keyboard::Num0:
        case sf::Keyboard::Numpad0:
            rig.recentre();
            return true;
        // The keys move the view, as if looking that way: D looks right, so the world slides left.
        case sf::Keyboard::A:
            rig.panPixels({step, 0.0f});
            return true;
        case sf::Keyboard::D:
            rig.panPixels({-step, 0.0f});
            return true;
        case sf::Keyboard::W:
            rig.panPixels({0.0f, step});
            return true;
        case sf::Keyboard::S:
            rig.panPixels({0.0f, -step});
            return true;
        default:
            return false;
        }
    }
    case sf::Event::LostFocus:
        m_dragFrom.reset();
        return false;
    default:
        return false;
    }
}

} // namespace abalike::app

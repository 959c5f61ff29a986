#pragma once

#include "screens/Screen.hpp"

namespace abalike::app
{

class App;

/// The help overlay (F1 or ? anywhere): every control, by keyboard and by mouse. Any key or click closes it.
class HelpScreen : public Screen
{
public:
    static constexpr std::string_view kName = "help";

    explicit HelpScreen(App& app) : m_app(app) {}

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    App& m_app;
};

} // namespace abalike::app

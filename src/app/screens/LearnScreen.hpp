#pragma once

#include "shell/Screen.hpp"
#include "ui/MenuList.hpp"

namespace abalike::app
{

class AppContext;

/// The title's Learn: the campaign with its physics shown (learn mode), the tutorial and the lessons. Arrows and
/// Enter, or hover and click; Esc goes back.
class LearnScreen : public Screen
{
public:
    static constexpr std::string_view kName = "learn";

    explicit LearnScreen(AppContext& app);

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    void activate(const std::string& id);

    AppContext& m_app;
    MenuList m_menu;
};

} // namespace abalike::app

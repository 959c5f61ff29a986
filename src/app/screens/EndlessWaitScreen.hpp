#pragma once

#include "shell/Screen.hpp"

namespace abalike::app
{

class AppContext;

/// The card shown while the endless run's next level is still being generated (every shipped level played, none
/// generated ahead yet): what the worker is doing, then the level as soon as it is ready. Esc goes to the title.
class EndlessWaitScreen : public Screen
{
public:
    static constexpr std::string_view kName = "endless-wait";

    explicit EndlessWaitScreen(AppContext& app);
    ~EndlessWaitScreen() override;

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void frameUpdate(double frameS) override;
    void draw(sf::RenderTarget& target) override;

private:
    AppContext& m_app;
    double m_waitedS = 0.0;
    bool m_leaving = false;
};

} // namespace abalike::app

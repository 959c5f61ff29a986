#pragma once

#include "shell/Screen.hpp"
#include "ui/MenuList.hpp"

#include <abalike/level/LevelDef.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The lessons, one per concept the campaign teaches, from the title menu: choose one to play its small level with
/// its guide. Arrows and Enter, or hover and click; Esc goes back.
class LessonSelectScreen : public Screen
{
public:
    static constexpr std::string_view kName = "lessons";

    explicit LessonSelectScreen(AppContext& app);

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    void open(const std::string& id);

    AppContext& m_app;
    MenuList m_menu;
    std::vector<std::optional<LevelDef>> m_levels; ///< by lessonList() index; empty where the file did not load
    std::vector<std::string> m_paths;
};

/// The folder of the lesson levels: lessons/ beside the campaign manifest.
std::string lessonsDirectory(const AppContext& app);

/// Plays the tutorial: the campaign's first level under the name "tutorial", with the tutorial guide.
void playTutorial(AppContext& app);

} // namespace abalike::app

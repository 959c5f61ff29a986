#include "screens/LessonSelectScreen.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "screens/MenuBackdrop.hpp"
#include "screens/PlayScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/UiMetrics.hpp"
#include "teach/Guide.hpp"
#include "ui/Card.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/TextValues.hpp>
#include <filesystem>

namespace abalike::app
{

std::string lessonsDirectory(const AppContext& app)
{
    return (std::filesystem::path(app.progress().campaign().manifestPath).parent_path() / "lessons").string();
}

void playTutorial(AppContext& app)
{
    // Its own level: three pigs apart and eight birds, so no first shot ends it before its last step.
    const std::string path = lessonsDirectory(app) + "/tutorial.json";
    try
    {
        LevelDef level = loadLevel(path, Catalog::builtin());
        app.navigator().screens().push(
            std::make_unique<PlayScreen>(app, PlaySource{std::move(level), path, std::nullopt, PlayMode::Learn}));
    }
    catch (const std::exception& error)
    {
        app.notices().notify(std::string("The tutorial cannot be opened: ") + error.what());
    }
}

LessonSelectScreen::LessonSelectScreen(AppContext& app) : m_app(app)
{
    std::vector<MenuItem> items;
    for (const LessonEntry& lesson : lessonList())
    {
        const std::string path = lessonsDirectory(app) + "/" + lesson.file;
        m_paths.push_back(path);
        try
        {
            m_levels.push_back(loadLevel(path, Catalog::builtin()));
        }
        catch (const std::exception& error)
        {
            // A missing or broken lesson file greys its entry out; the others still play.
            m_levels.push_back(std::nullopt);
            app.notices().notify("Lesson \"" + lesson.title + "\" could not be loaded from " + path);
        }
        items.push_back({lesson.id, lesson.title, m_levels.back().has_value()});
    }
    items.push_back({"back", "Back", true});
    m_menu.setItems(std::move(items));
}

void LessonSelectScreen::handleEvent(const sf::Event& event)
{
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Escape)
    {
        m_app.navigator().screens().pop();
        return;
    }
    if (const std::optional<std::string> id = m_menu.handleEvent(event))
        open(*id);
}

void LessonSelectScreen::open(const std::string& id)
{
    if (id == "back")
    {
        m_app.navigator().screens().pop();
        return;
    }
    for (std::size_t i = 0; i < lessonList().size(); ++i)
        if (lessonList()[i].id == id && m_levels[i])
            m_app.navigator().screens().push(std::make_unique<PlayScreen>(
                m_app, PlaySource{*m_levels[i], m_paths[i], std::nullopt, PlayMode::Learn}));
}

void LessonSelectScreen::draw(sf::RenderTarget& target)
{
    const float y =
        drawMenuBackdrop(target, m_app, "Lessons", "One idea each, learnt by doing: a small level and a guide", 0.06f);
    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    const float centre = 0.5f * window.x;
    const sf::Font* font = m_app.ui().font();
    const float bottom = m_menu.draw(target, font, centre, y, std::min(window.x - 40.0f, 360.0f * scale),
                                     m_app.ui().textSize(21.0f), scale);
    if (font == nullptr)
        return;
    // What the highlighted lesson teaches, in the level's own words.
    const std::size_t selected = m_menu.selected();
    if (selected < m_levels.size() && m_levels[selected])
    {
        const unsigned size = m_app.ui().textSize(17.0f);
        float line = bottom + 18.0f * scale;
        // Its {values} filled from its own level, as level select and `check --texts` show them.
        const std::string lesson = levelText(m_levels[selected]->lesson, *m_levels[selected], Catalog::builtin());
        for (const std::string& text : wrapText(*font, lesson, size, std::min(window.x - 60.0f, 760.0f * scale)))
        {
            drawLabel(target, *font, utf8(text), {centre, line}, size, palette::kText, Align::Centre);
            line += font->getLineSpacing(size);
        }
    }
}

} // namespace abalike::app

#pragma once

#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// What a guide's steps may look at to decide that the player has done what a step asked.
struct GuideContext
{
    const GameSession* session = nullptr;
    std::optional<AimReadout> aim;
    std::optional<AimReadout> firstAim; ///< the aim when the guide started
    bool overlayOn = false;
    bool chartOn = false;
    bool comparisonOn = false;
    bool walkthroughOn = false;
    bool measured = false;         ///< a path point was read or the tape used since the guide started
    bool predictionLocked = false; ///< predict-then-launch: a prediction is locked for the aim shown
    int predictionsAnswered = 0;   ///< predict-then-launch: predictions compared with a flight so far
    int shotsAtStepStart = 0;
    int shots() const { return static_cast<int>(session->shots().size()); }
};

/// One thing to do: what to read, and when it is done.
struct GuideStep
{
    std::string text;
    std::function<bool(const GuideContext&)> done;
};

/// A guide teaches by doing: one step at a time, each done when the player has done it. The first-run tutorial
/// and the lessons are guides.
struct Guide
{
    std::string title;
    std::vector<GuideStep> steps;
    std::string closing; ///< shown once every step is done
};

/// Runs a guide on the play screen: checks the current step every frame and draws its card.
class GuideRunner
{
public:
    void start(Guide guide);
    void stop() { m_guide.reset(); }
    bool active() const { return m_guide.has_value(); }
    /// The step the player is on (steps().size() once done).
    std::size_t step() const { return m_step; }
    /// Every step is done.
    bool finished() const { return m_guide && m_step >= m_guide->steps.size(); }

    /// Checks the current step (and the next ones: several can be done at once).
    void update(GuideContext context);
    /// The card: the guide's title, the step's text and how far along it is; `topLeft` its corner. Where the whole
    /// card has no room (panelHasRoom) it keeps the lines that fit, the last cut with an ellipsis, and with no room
    /// for its title it is left out. Returns its bounds (empty when left out).
    sf::FloatRect draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topLeft, float maxWidth,
                       unsigned titleSize, unsigned rowSize, float scale) const;

private:
    std::optional<Guide> m_guide;
    std::size_t m_step = 0;
    int m_shotsAtStepStart = 0;
    std::optional<AimReadout> m_firstAim;
};

/// The guide for a level, if it has one: the tutorial for level id "tutorial" (levels/lessons/tutorial.json), a
/// lesson for "lesson-..." levels.
std::optional<Guide> guideFor(const LevelDef& level, const Catalog& catalog);
/// The tutorial itself.
Guide tutorialGuide();
/// The tutorial level's id (levels/lessons/tutorial.json), and its key in the progress once it is finished.
inline constexpr const char* kTutorialId = "tutorial";

/// A lesson the title menu offers: its level file (in levels/lessons/) and what it teaches.
struct LessonEntry
{
    std::string id;
    std::string title;
    std::string file;
};

/// One short interactive lesson per concept the campaign teaches.
const std::vector<LessonEntry>& lessonList();

} // namespace abalike::app

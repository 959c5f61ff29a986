#include "teach/TeachLayer.hpp"

#include "render/ScreenRegions.hpp"

#include "play/PlayToolbar.hpp"
#include "render/LabelPlacement.hpp"
#include "shell/AppContext.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"
#include "teach/BandGraph.hpp"
#include "teach/ForceArrows.hpp"
#include "teach/ImpactPanel.hpp"
#include "teach/TeachDraw.hpp"
#include "teach/WhyPanel.hpp"

#include <abalike/save/AtomicWrite.hpp>
#include <abalike/save/DataDirectory.hpp>
#include <abalike/teach/ShotTable.hpp>
#include <abalike/world/Catalog.hpp>
#include <filesystem>
#include <system_error>

namespace abalike::app
{

bool TeachLayer::overlayOn() const
{
    return m_app.settings().current().teachingOverlay;
}

void TeachLayer::toggleOverlay()
{
    Settings settings = m_app.settings().current();
    settings.teachingOverlay = !settings.teachingOverlay;
    m_app.settings().update(settings); // a scripted run changes it for this run only
    m_app.notices().notify(
        settings.teachingOverlay ? "Teaching overlay on (T to hide)" : "Teaching overlay off (T to show)", "overlay");
}

void TeachLayer::exportShots(const PlayView& view)
{
    const GameSession& session = view.session();
    if (session.shots().empty())
    {
        m_app.notices().notify("No shot to export yet: launch a bird first (E exports every shot of this level)");
        return;
    }
    const std::filesystem::path dataDir = defaultDataDirectory();
    if (dataDir.empty())
    {
        m_app.notices().notify("Cannot export: no data folder (set HOME or ABALIKE_DATA_DIR)");
        return;
    }
    // exports/LEVEL-shots-N.csv with the first free N: an export never overwrites an earlier one.
    const std::filesystem::path folder = dataDir / "exports";
    std::string stem = session.level().id.empty() ? std::string("level") : session.level().id;
    for (char& c : stem)
        if (c == '/' || c == '\\')
            c = '_';
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    std::filesystem::path path;
    for (int n = 1; n < 100000; ++n)
    {
        path = folder / (stem + "-shots-" + std::to_string(n) + ".csv");
        if (!std::filesystem::exists(path, error))
            break;
    }
    try
    {
        writeFileAtomically(path, shotTableCsv(session));
        m_app.notices().notify("Exported " + std::to_string(session.shots().size()) + " shot(s) to " + path.string());
    }
    catch (const std::exception& e)
    {
        m_app.notices().notify(std::string("Cannot export the shots: ") + e.what());
    }
}

bool TeachLayer::handleEvent(const sf::Event& event, PlayView& view)
{
    // The integrator tools show the numerical machinery itself: university wording only.
    if (!m_app.settings().universityWording() && event.type == sf::Event::KeyPressed && !event.key.control &&
        !event.key.alt && (event.key.code == sf::Keyboard::K || event.key.code == sf::Keyboard::I) &&
        !m_walkthrough.active())
    {
        m_app.notices().notify(
            "The step-by-step method tools come with the university wording (Settings \u2192 Wording)");
        return true;
    }
    if (m_quiz.handleEvent(event, view))
        return true;
    if (m_walkthrough.handleEvent(event, view, m_follower))
        return true;
    if (event.type == sf::Event::KeyPressed && !event.key.control && !event.key.alt)
    {
        switch (event.key.code)
        {
        case sf::Keyboard::T:
            toggleOverlay();
            return true;
        case sf::Keyboard::G:
            m_showChart = !m_showChart;
            return true;
        case sf::Keyboard::C:
            m_paths.clear();
            view.clearTrails();
            return true;
        case sf::Keyboard::V:
            m_components = !m_components;
            m_app.notices().notify(m_components ? "Velocity components vx and vy shown (V to hide)"
                                                : "Velocity components hidden (V to show)",
                                   "components");
            return true;
        case sf::Keyboard::Z:
            view.slowMotion().cycle();
            m_app.notices().notify(
                std::string("Speed ") + view.slowMotion().label() +
                    (view.slowMotion().divisor() == 1 ? " (real time)" : " (slow motion; the physics is unchanged)"),
                "speed");
            return true;
        case sf::Keyboard::E:
            exportShots(view);
            return true;
        default:
            if (m_comparison.handleKey(event.key))
                return true;
            break;
        }
    }
    // The measuring tools work with the overlay, and always while a guide runs (the tutorial has a measuring step,
    // and a player who hid the overlay again must not be stuck on it).
    if (!overlayOn() && !m_guide.active())
        return false;
    if (event.type == sf::Event::KeyPressed && !event.key.control && !event.key.alt &&
        m_paths.handleKey(event.key, view))
        return true;
    return m_paths.handleEvent(event, view);
}

void TeachLayer::onLevelStart(PlayView& view)
{
    const std::string& id = view.session().level().id;
    if (id != m_guideLevel)
    {
        m_guideLevel = id;
        std::optional<Guide> guide = guideFor(view.session().level(), view.session().catalog());
        if (guide)
            m_guide.start(std::move(*guide));
        else
            m_guide.stop();
    }
    m_walkthrough.stop(view);
    m_follower.reset();
    m_paths.onLevelStart();
    m_feedback.reset();
    m_quiz.reset();
    forgetShrunkPanels();
}

void TeachLayer::frameUpdate(PlayView& view, double frameS)
{
    (void)frameS;
    const GameSession& session = view.session();
    const bool aiming = session.phase() == Phase::Aiming;
    if (aiming && !m_aimingBefore)
        forgetShrunkPanels();
    m_aimingBefore = aiming;
    m_feedback.update(session, view.aim());
    m_quiz.update(session, view.aim());
    m_comparison.update(session, view.preview());
    GuideContext context;
    context.session = &session;
    context.aim = view.aim();
    context.overlayOn = overlayOn();
    context.chartOn = m_showChart;
    context.comparisonOn = m_comparison.active();
    context.walkthroughOn = m_walkthrough.active();
    context.measured = m_paths.used();
    context.predictionLocked = m_quiz.locked();
    context.predictionsAnswered = m_quiz.answered();
    m_guide.update(context);
    // The tutorial, once finished, is kept in the progress (as "tutorial", which no campaign level is): the title's
    // Learn menu marks it done, and nothing starts it again.
    if (m_guide.finished() && session.level().id == kTutorialId &&
        !m_app.progress().current().levels.contains(kTutorialId))
        m_app.progress().recordResult(kTutorialId, 0, 1);
    if (m_showChart)
        m_chart.update(session, view.aim());
}

void TeachLayer::drawWorld(sf::RenderTarget& target, PlayView& view)
{
    const TextKindScope physics(TextKind::Physics);
    const float scale = m_app.ui().scale();
    if (overlayOn())
        PathHistory::drawDots(target, view.trails(), view.camera(), scale);
    const sf::Font* font = m_app.ui().font();
    m_comparison.drawWorld(target, view.camera(), scale);
    if (m_walkthrough.active())
        m_walkthrough.drawWorld(target, view.camera(), scale);
    else if (overlayOn() && font != nullptr)
        if (const std::optional<BirdReadout> bird = m_follower.current(view.session()))
            drawForceArrows(target, *font, view.camera(), *bird, m_components, m_app.ui().textSize(13.0f), scale);
}

void TeachLayer::drawScreen(sf::RenderTarget& target, PlayView& view)
{
    const sf::Font* font = m_app.ui().font();
    if (font == nullptr)
        return;
    // The overlay's panels are physics with their numbers; a lesson's step is a hint (below).
    const TextKindScope physics(TextKind::Physics);
    const GameSession& session = view.session();
    const float scale = m_app.ui().scale();
    const unsigned titleSize = m_app.ui().textSize(15.0f);
    const unsigned rowSize = m_app.ui().textSize(13.0f);
    const float margin = 12.0f * scale;
    const float gap = 6.0f * scale;
    const sf::Vector2f window(target.getSize());
    const bool aiming = session.phase() == Phase::Aiming;
    // The columns' large panels, a lesson's step and the feedback leave the slingshot, the flying bird and live pigs
    // in view, or shrink.
    std::vector<ScreenRegion> things;
    if (overlayOn() || feedbackShown(view) || m_guide.active() || PredictQuizView::wanted(session.level()))
        things = keepVisibleBoxes(session, view.camera());
    const std::vector<sf::FloatRect> keep = rectsOf(things);
    setKeepInView(std::move(things));

    // Right column: the flying bird's forces and energy, or after its first contact the impact; while aiming, the
    // chart and the comparison.
    sf::Vector2f right(window.x - margin, PlayToolbar::bottomPx(PlayToolbar::buttonScale(m_app)) + gap);
    // The columns start under whatever the HUD drew where they go (the aim readout reaches into them in narrow
    // windows and at large text): ScreenRegions holds this frame's panels so far.
    const float rightWidth = std::min(470.0f * scale, window.x - 2.0f * margin);
    const float minHeight = 40.0f * scale;
    const auto clearRight = [&]
    {
        right.y = firstFreeTop(right.x - rightWidth, rightWidth, right.y, minHeight, gap);
    };
    const auto below = [&](const sf::FloatRect& rect)
    {
        if (rect.height > 0.0f)
            right.y = rect.top + rect.height + gap;
        clearRight();
    };
    clearRight();
    if (overlayOn() && !m_walkthrough.active())
    {
        const unsigned terms = m_follower.model() ? activeTerms(*m_follower.model()) : 0u;
        const bool drag = (terms & (kLinearDragTerm | kQuadraticDragTerm)) != 0;
        const bool wind = (terms & (kWindTerm | kGustTerm)) != 0;
        if (const std::optional<BirdReadout> bird = m_follower.current(session))
        {
            below(drawForceLegend(target, *font, right, *bird, drag, wind, m_components, titleSize, rowSize, scale));
            below(drawEnergyBars(target, *font, right, bird->energy, false, titleSize, rowSize, scale));
        }
        else if (!aiming && !session.shots().empty())
        {
            const ShotRecord& shot = session.shots().back();
            if (shot.energy)
                below(drawEnergyBars(target, *font, right, *shot.energy, true, titleSize, rowSize, scale));
            if (shot.impact)
            {
                // The impact panel is as wide as its numbers need, its right edge on the column's.
                below(drawImpactPanel(target, *font, right, *shot.impact, m_app.settings().universityWording(),
                                      titleSize, rowSize, scale));
            }
        }
    }
    // While aiming, the aim readout sits at the top centre: the chart and the comparison go below it.
    if (aiming)
        clearRight();
    if (aiming && overlayOn())
        if (const std::optional<AimReadout> aim = view.aim())
        {
            // Its own size is known: it goes where all of it is clear, or (no room left, or it would cover the
            // slingshot or a pig) is left out.
            const sf::Vector2f size = BandGraph::measure(*font, titleSize, rowSize, scale);
            const float top = firstFreeTop(right.x - size.x, size.x, right.y, size.y, gap);
            if (fullPanelFits(target, {{right.x - size.x, top}, size}, "aim graph"))
                below(BandGraph::draw(target, *font, {right.x, top}, *aim, titleSize, rowSize, scale));
        }
    if (m_showChart && aiming)
        below(m_chart.draw(target, *font, right, titleSize, rowSize, scale));
    if (aiming)
        below(m_comparison.drawPanel(target, *font, right, titleSize, rowSize, scale));

    // Left column, under the level's status and air: a tutorial's or lesson's step, why preview and world can differ.
    const float leftWidth = std::min(440.0f * scale, window.x - 2.0f * margin);
    float left = 152.0f * scale;
    const auto clearLeft = [&]
    {
        left = firstFreeTop(margin, leftWidth, left, minHeight, gap);
    };
    // The prediction card first: what the player types into must keep its room; the lesson's step shortens to fit.
    // It finds its own place down the column by its own width.
    if (PredictQuizView::wanted(session.level()) && !m_walkthrough.active())
    {
        const sf::FloatRect card = m_quiz.draw(target, *font, {margin, left}, titleSize, rowSize, scale);
        if (card.height > 0.0f) // left out when it had no room
            left = card.top + card.height + gap;
    }
    clearLeft();
    if (m_guide.active() && !m_walkthrough.active())
    {
        const TextKindScope hint(TextKind::Hint);
        const sf::FloatRect card =
            m_guide.draw(target, *font, {margin, left}, std::min(440.0f * scale, window.x - 2.0f * margin),
                         m_app.ui().textSize(17.0f), m_app.ui().textSize(15.0f), scale);
        if (card.height > 0.0f) // left out when it had no room
            left = card.top + card.height + gap;
        clearLeft();
    }
    // A panel with no room left under the others is left out rather than drawn over them or off the window.
    const bool roomLeft = left + minHeight <= window.y;
    if (overlayOn() && !m_walkthrough.active() && roomLeft)
        drawWhyPanel(target, *font, {margin, left}, session, view.preview(), m_app.settings().universityWording(),
                     titleSize, rowSize, scale);

    if (m_walkthrough.active())
        m_walkthrough.drawPanel(target, *font, 152.0f * scale, titleSize, rowSize, scale);

    // Feedback on the last shot, above the level's hint and the app's notices at the bottom: the physics of the shot
    // in words, in learn mode only (the game mode keeps the picture: the flown path beside the predicted dots).
    if (!m_walkthrough.active() && feedbackShown(view))
        m_feedback.draw(target, *font, window.y - 96.0f * scale, 160.0f * scale,
                        structureScreenBoxes(session, view.camera()), keep, std::min(window.x - 40.0f, 900.0f * scale),
                        m_app.ui().textSize(16.0f), scale);

    // The measuring tools last: what the player points at reads over everything.
    if (overlayOn() || m_guide.active())
        m_paths.drawTools(target, *font, view.camera(), session, rowSize, scale);
}

bool TeachLayer::hidesPreview(const PlayView& view) const
{
    return PredictQuizView::wanted(view.session().level()) && view.session().phase() == Phase::Aiming &&
           !m_quiz.locked();
}

} // namespace abalike::app

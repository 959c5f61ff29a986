#pragma once

#include "play/PlayLayer.hpp"
#include "teach/BirdReadout.hpp"
#include "teach/ComparisonView.hpp"
#include "teach/FeedbackView.hpp"
#include "teach/Guide.hpp"
#include "teach/PathHistory.hpp"
#include "teach/PredictQuizView.hpp"
#include "teach/RangeChartView.hpp"
#include "teach/WalkthroughView.hpp"

namespace abalike::app
{

/// The teaching aids on the play screen (issue 11). T (or the teaching_overlay setting) shows the force arrows and
/// energy bars on the flying bird, the first impact in numbers, the timing dots on the last shots' paths with the
/// measuring tools, and why the preview and the world can differ; G the range-by-angle chart; I the integrator
/// comparison; K the RK4 walkthrough; C clears the kept paths. The feedback sentences after a shot are always on, and
/// so is the guide of a tutorial or lesson level.
class TeachLayer : public PlayLayer
{
public:
    explicit TeachLayer(AppContext& app) : m_app(app) {}

    std::string_view name() const override { return "teach"; }
    bool handleEvent(const sf::Event& event, PlayView& view) override;
    void onLevelStart(PlayView& view) override;
    void frameUpdate(PlayView& view, double frameS) override;
    void drawWorld(sf::RenderTarget& target, PlayView& view) override;
    void drawScreen(sf::RenderTarget& target, PlayView& view) override;
    /// "Predict, then launch": the preview would show the answer, so it waits until the prediction is locked in.
    bool hidesPreview(const PlayView& view) const override;

private:
    /// The sentences on the last shot: in learn mode, when there are any.
    bool feedbackShown(const PlayView& view) const
    {
        return view.playMode() == PlayMode::Learn && !m_feedback.sentences().empty();
    }
    bool overlayOn() const;
    void toggleOverlay();
    /// Writes every shot of this level so far as CSV (key E) into the data folder's exports/ and says where.
    void exportShots(const PlayView& view);

    AppContext& m_app;
    ShotFollower m_follower;
    PathHistory m_paths;
    ComparisonView m_comparison;
    RangeChartView m_chart;
    WalkthroughView m_walkthrough;
    FeedbackView m_feedback;
    PredictQuizView m_quiz;
    GuideRunner m_guide;
    std::string m_guideLevel; ///< the level the guide was started for: a restart keeps its progress
    /// The last frame's phase was aiming: the panels that shrank during a shot grow back on the next aim.
    bool m_aimingBefore = true;
    bool m_showChart = false;
    bool m_components = false; ///< vx and vy arrows beside v (key V)
};

} // namespace abalike::app

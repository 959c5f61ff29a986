#pragma once

#include "render/Camera.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/teach/IntegratorComparison.hpp>
#include <optional>

namespace abalike::app
{

/// Beyond PhET: next to the real RK4 preview, the path another integrator would predict -- explicit Euler,
/// semi-implicit Euler (Box2D's scheme), RK4 at another step, or dopri5 at a tolerance -- with its error against
/// the real path and what it costs. Only this drawing changes: the preview and the world stay RK4 at 1/60 s.
class ComparisonView
{
public:
    /// I: next method (or off); [ and ]: a coarser or finer step (tolerance for dopri5). True when used.
    bool handleKey(const sf::Event::KeyEvent& key);
    bool active() const { return m_method > 0; }
    /// Recomputes when the preview or the method changed.
    void update(const GameSession& session, const PredictedFlight* preview);
    void drawWorld(sf::RenderTarget& target, const Camera& camera, float scale) const;
    /// The numbers; `topRight` is the panel's top-right corner. Returns its bounds (empty when off).
    sf::FloatRect drawPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight, unsigned titleSize,
                            unsigned rowSize, float scale) const;

    /// The method compared now (meaningless while off).
    ComparisonMethod method() const;

private:
    int m_method = 0;    ///< 0 off, then euler, semi-implicit euler, rk4, dopri5
    int m_stepIndex = 3; ///< into the step rates (1/60 s) or, for dopri5, the tolerances
    bool m_dirty = true;
    const PredictedFlight* m_lastPreview = nullptr;
    std::size_t m_lastPreviewSteps = 0;
    std::optional<PathPoint> m_lastPreviewEnd;
    std::optional<IntegratorComparison> m_result;
    std::size_t m_realEvaluations = 0;
};

} // namespace abalike::app

#pragma once

#include "play/PlayLayer.hpp"

#include <string>

namespace abalike::app
{

/// Says plainly, on every play screen (and the editor's play mode), when the world collides the bird in the
/// slingshot or in flight as something else than it is: a custom bird smaller than 0.1 m or heavier than ten times
/// the lightest block or pig is flown with its true size and mass but collides as a clamped body (BirdBody.hpp).
class BirdBodyNotice : public PlayLayer
{
public:
    std::string_view name() const override { return "bird-body-notice"; }
    void frameUpdate(PlayView& view, double frameS) override;
    void drawScreen(sf::RenderTarget& target, PlayView& view) override;

private:
    std::string m_text; ///< what to say about the current bird; empty when it is its own body
    int m_told = -1;    ///< the bird (by number) whose notice went to the trace and stderr
};

} // namespace abalike::app

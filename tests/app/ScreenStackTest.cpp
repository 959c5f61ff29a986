#include "shell/ScreenStack.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace abalike::app
{
namespace
{

/// A screen that writes what happens to it into a shared log.
class FakeScreen : public Screen
{
public:
    FakeScreen(std::string name, std::vector<std::string>& log, bool overlay = false)
        : m_name(std::move(name)), m_log(log), m_overlay(overlay)
    {
    }
    ~FakeScreen() override { m_log.push_back("destroy " + m_name); }

    std::string_view name() const override { return m_name; }
    bool isOverlay() const override { return m_overlay; }
    void handleEvent(const sf::Event&) override {}
    void draw(sf::RenderTarget&) override { m_log.push_back("draw " + m_name); }
    void onResume() override { m_log.push_back("resume " + m_name); }
    void onResize(sf::Vector2u size) override { m_log.push_back("resize " + m_name + " " + std::to_string(size.x)); }

private:
    std::string m_name;
    std::vector<std::string>& m_log;
    bool m_overlay;
};

/// A render target that draws nowhere, so the stack can be tested without a display.
class NullTarget : public sf::RenderTarget
{
public:
    sf::Vector2u getSize() const override { return {640, 480}; }
    bool setActive(bool) override { return true; }
};

TEST(ScreenStack, ChangesWaitUntilTheFrameIsOver)
{
    std::vector<std::string> log;
    ScreenStack stack;
    stack.push(std::make_unique<FakeScreen>("title", log));
    EXPECT_TRUE(stack.empty()) << "a push is applied after the frame";
    EXPECT_TRUE(stack.hasPending());
    EXPECT_TRUE(stack.applyPending());
    ASSERT_EQ(stack.names(), (std::vector<std::string>{"title"}));

    // A screen asking for its own removal stays alive until the frame ends.
    Screen* title = stack.top();
    stack.pop();
    stack.push(std::make_unique<FakeScreen>("play", log));
    EXPECT_EQ(stack.top(), title);
    EXPECT_TRUE(log.empty());
    stack.applyPending();
    EXPECT_EQ(stack.names(), (std::vector<std::string>{"play"}));
    EXPECT_EQ(log, (std::vector<std::string>{"destroy title"}));
    EXPECT_FALSE(stack.applyPending()) << "nothing left to apply";
}

TEST(ScreenStack, AnUncoveredScreenIsResumedButANewOneIsNot)
{
    std::vector<std::string> log;
    ScreenStack stack;
    stack.push(std::make_unique<FakeScreen>("play", log));
    stack.push(std::make_unique<FakeScreen>("pause", log, true));
    stack.applyPending();
    EXPECT_TRUE(log.empty()) << "pushed screens are not resumed";
    stack.pop();
    stack.applyPending();
    EXPECT_EQ(log, (std::vector<std::string>{"destroy pause", "resume play"}));

    log.clear();
    stack.replace(std::make_unique<FakeScreen>("next", log));
    stack.applyPending();
    EXPECT_EQ(log, (std::vector<std::string>{"destroy play"}));
    EXPECT_EQ(stack.names(), (std::vector<std::string>{"next"}));
}

TEST(ScreenStack, ClearThenPushStartsOver)
{
    std::vector<std::string> log;
    std::vector<std::string> changes;
    ScreenStack stack;
    stack.setObserver([&changes](std::string_view change, std::string_view screen)
                      { changes.push_back(std::string(change) + " " + std::string(screen)); });
    stack.push(std::make_unique<FakeScreen>("title", log));
    stack.push(std::make_unique<FakeScreen>("play", log));
    stack.push(std::make_unique<FakeScreen>("pause", log, true));
    stack.applyPending();
    stack.clear();
    stack.push(std::make_unique<FakeScreen>("title", log));
    stack.push(std::make_unique<FakeScreen>("level-select", log));
    stack.applyPending();
    EXPECT_EQ(stack.names(), (std::vector<std::string>{"title", "level-select"}));
    EXPECT_EQ(changes, (std::vector<std::string>{"push title", "push play", "push pause", "pop pause", "pop play",
                                                 "pop title", "push title", "push level-select"}));
}

TEST(ScreenStack, DrawsFromTheTopmostFullScreenUp)
{
    std::vector<std::string> log;
    ScreenStack stack;
    stack.push(std::make_unique<FakeScreen>("title", log));
    stack.push(std::make_unique<FakeScreen>("play", log));
    stack.push(std::make_unique<FakeScreen>("pause", log, true));
    stack.push(std::make_unique<FakeScreen>("help", log, true));
    stack.applyPending();
    NullTarget target;
    stack.draw(target);
    EXPECT_EQ(log, (std::vector<std::string>{"draw play", "draw pause", "draw help"}));

    log.clear();
    stack.resize({800, 600});
    EXPECT_EQ(log,
              (std::vector<std::string>{"resize title 800", "resize play 800", "resize pause 800", "resize help 800"}));
}

TEST(ScreenStack, PopOnAnEmptyStackIsHarmless)
{
    ScreenStack stack;
    stack.pop();
    EXPECT_TRUE(stack.applyPending());
    EXPECT_TRUE(stack.empty());
    EXPECT_EQ(stack.top(), nullptr);
}

} // namespace
} // namespace abalike::app

// What the learner reads is what was checked: every text the game draws on the screens that show level or lesson
// text (title, level select, learn, lessons, play, results, pause, help), for every campaign level and lesson, in
// both wordings and both modes, at the default window (1280x720, text 100 %). A text fails on an unfilled
// placeholder ("{launch_height}"), a sentence cut short ("..."), or, in school wording, a term of the one list of
// university-only terms (abalike/teach/SchoolWording.hpp). Runs in this process with frames laid out, as the layout
// walk does.
#include "Walk.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/SchoolWording.hpp>

#include <array>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace abalike::app
{
namespace
{

using namespace walk;

struct TextSetting
{
    const char* wording;
    const char* mode;
    bool overlay; ///< the teaching overlay shows the most text; game mode is walked as a player has it, without
};

constexpr std::array<TextSetting, 4> kTextSettings{{
    {"school", "learn", true},
    {"school", "game", false},
    {"university", "learn", true},
    {"university", "game", false},
}};

nlohmann::json settingsFile(const TextSetting& setting)
{
    return {{"format", 1},
            {"wording", setting.wording},
            {"mode", setting.mode},
            {"teaching_overlay", setting.overlay},
            {"open_all_levels", true}};
}

std::string describe(const TextSetting& setting)
{
    return std::string(setting.wording) + " wording, " + setting.mode + " mode";
}

/// What is wrong with one drawn text; empty when nothing is.
std::vector<std::string> textProblems(const std::string& text, bool school)
{
    static const std::regex placeholder(R"(\{[A-Za-z_][^{}]*\})");
    std::vector<std::string> problems;
    if (std::smatch match; std::regex_search(text, match, placeholder))
        problems.push_back("unfilled placeholder " + match.str());
    if (text.find("\u2026") != std::string::npos)
        problems.push_back("cut short");
    if (school)
        if (const std::optional<std::string_view> term = universityTermIn(text))
            problems.push_back("school wording shows \"" + std::string(*term) + "\"");
    return problems;
}

/// Checks every text of every laid-out frame; keeps each problem once, with the first frame it was seen in.
class TextObserver final : public FrameObserver
{
public:
    TextObserver(bool school, int every) : m_school(school), m_every(every) {}
    int layoutEvery() const override { return m_every; }
    void laidOut(const FrameLayout& frame) override
    {
        ++m_frames;
        for (const DrawnText& text : frame.texts)
        {
            m_seen.insert(text.text);
            for (const std::string& problem : textProblems(text.text, m_school))
                m_problems.emplace(problem + " in \"" + text.text + "\"", frame.frame);
        }
    }

    int frames() const { return m_frames; }
    const std::set<std::string>& seen() const { return m_seen; }
    const std::map<std::string, long long>& problems() const { return m_problems; }

private:
    bool m_school;
    int m_every;
    int m_frames = 0;
    std::set<std::string> m_seen;
    std::map<std::string, long long> m_problems;
};

bool anySeenContains(const TextObserver& observer, const std::string& part)
{
    for (const std::string& text : observer.seen())
        if (text.find(part) != std::string::npos)
            return true;
    return false;
}

void reportProblems(const TextObserver& observer, const std::string& where)
{
    for (const auto& [problem, frame] : observer.problems())
        ADD_FAILURE() << where << ", frame " << frame << ": " << problem;
}

ScriptEvent tap(int frame, const char* key)
{
    ScriptEvent event;
    event.frame = frame;
    event.key = key;
    return event;
}

TEST(TextWalkUnit, TheChecksFindWhatTheyLookFor)
{
    // The walk's own checks on texts written to fail them, so that a walk that passes means something.
    EXPECT_EQ(textProblems("the best is {vacuum_best_angle:red} degrees", false).size(), 1u);
    EXPECT_EQ(textProblems("The wind moved the landing point 2.1 m forward: 12.3 m instead of\u2026", false).size(),
              1u);
    EXPECT_EQ(textProblems("Box2D owns the bird (4 sub-steps)", true).size(), 1u);
    EXPECT_TRUE(textProblems("Box2D owns the bird (4 sub-steps)", false).empty());
    EXPECT_TRUE(textProblems("Score  12 500 \u00B7 Birds left 2", true).empty());
    EXPECT_TRUE(universityTermIn("restitution e = separating / closing speed").has_value());
    EXPECT_TRUE(universityTermIn("spin 3.1 rad/s").has_value());
    EXPECT_FALSE(universityTermIn("a chordata of subtoitles").has_value()); // whole words only
    EXPECT_EQ(universityTermIn("balance off by 2.1e-07 J"), "scientific notation");
    EXPECT_EQ(universityTermIn("118 steps, 473 force evaluations"), "evaluation");
    EXPECT_FALSE(universityTermIn("the free energy at 12 m, 3 birds").has_value()) << "an e after a letter is a word";
}

class TextWalk : public ::testing::TestWithParam<std::string>
{
};

TEST_P(TextWalk, EveryTextOfTheLevelIsFilledWholeAndInItsWording)
{
    // The level paused, resumed, help and its second page, closed; then played with its reference shot twice
    // (aiming, flight, impact, the next bird, the results when it ends).
    const std::string& path = GetParam();
    const LevelDef level = loadLevel(path, Catalog::builtin());
    ASSERT_TRUE(level.referenceShot.has_value()) << path;
    const ScratchData data("text-walk");
    const int frames = framesFor(level);
    for (const TextSetting& setting : kTextSettings)
    {
        TextObserver observer(std::string(setting.wording) == "school", kLayoutEvery);
        AppOptions options;
        options.levelPath = path;
        options.level = level;
        options.frames = frames;
        options.shots = walkedShots(level);
        options.width = 1280u;
        options.height = 720u;
        // (Help counts its pages when it is first laid out: its page key comes a laid-out frame after it opens.)
        options.script.events = {tap(4, "Escape"), tap(8, "Escape"), tap(12, "F1"), tap(20, "Right"), tap(24, "F1")};
        options.hasScript = true;
        options.observer = &observer;
        const std::string where = level.id + " in " + describe(setting);
        ASSERT_EQ(playLaidOut(std::move(options), settingsFile(setting), data), 0) << where;
        EXPECT_EQ(observer.frames(), frames / kLayoutEvery) << where;
        // It walked what it claims: the level's own words, the pause menu and the help.
        EXPECT_TRUE(anySeenContains(observer, level.title)) << where;
        EXPECT_TRUE(anySeenContains(observer, "Resume")) << where << ": the pause menu was not walked";
        EXPECT_TRUE(anySeenContains(observer, "Page 2 of")) << where << ": help's second page was not walked";
        reportProblems(observer, where);
    }
}

INSTANTIATE_TEST_SUITE_P(CampaignAndLessons, TextWalk, ::testing::ValuesIn(walkedLevels()), walkedLevelName);

TEST(TextWalkMenus, EveryLevelAndLessonInTheMenusIsFilledWholeAndInItsWording)
{
    // From the title (every level open, as on a class machine): level select through every tile, back, Learn,
    // Lessons through every lesson, back to the title, help and its next page.
    const Campaign campaign = loadCampaignLevels((kSource / "levels/campaign.json").string(), Catalog::builtin());
    ASSERT_FALSE(campaign.levels.empty());
    const ScratchData data("text-walk-menus");
    for (const TextSetting& setting : kTextSettings)
    {
        std::vector<ScriptEvent> events{tap(2, "Down"), tap(4, "Enter")};
        // Level select opens on the level the progress is at: to the first, then through every one.
        int frame = 6;
        for (const char* key : {"Left", "Right"})
            for (std::size_t i = 0; i + 1 < campaign.levels.size(); ++i, frame += 2)
                events.push_back(tap(frame, key));
        // Back on the title at Level select: down past Endless castles to Learn, then Lessons.
        for (const char* key : {"Escape", "Down", "Down", "Enter", "Down", "Down", "Enter"})
            events.push_back(tap(frame += 2, key));
        for (int lesson = 0; lesson < 10; ++lesson)
            events.push_back(tap(frame += 2, "Down"));
        for (const char* key : {"Escape", "Escape", "F1"})
            events.push_back(tap(frame += 2, key));
        events.push_back(tap(frame += 4, "Right"));
        TextObserver observer(std::string(setting.wording) == "school", 2);
        AppOptions options;
        options.campaignPath = (kSource / "levels/campaign.json").string();
        options.frames = frame + 2;
        options.width = 1280u;
        options.height = 720u;
        options.script.events = std::move(events);
        options.hasScript = true;
        options.observer = &observer;
        const std::string where = "the menus in " + describe(setting);
        ASSERT_EQ(playLaidOut(std::move(options), settingsFile(setting), data, campaign), 0) << where;
        // Every level's title in level select, every lesson's in the lessons menu, and help.
        for (const CampaignLevel& level : campaign.levels)
            EXPECT_TRUE(anySeenContains(observer, level.level.title))
                << where << ": " << level.level.title << " never shown";
        EXPECT_TRUE(anySeenContains(observer, "Predict, then launch")) << where << ": the lessons were not walked";
        EXPECT_TRUE(anySeenContains(observer, "Page 2 of")) << where << ": help's second page was not walked";
        reportProblems(observer, where);
    }
}

} // namespace
} // namespace abalike::app

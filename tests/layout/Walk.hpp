#pragma once

// What the layout walk and the text walk share: the levels they walk, a scratch folder for the player's files, one
// window per size, and how long a level is walked.

#include "render/Font.hpp"
#include "screens/GameScreens.hpp"
#include "shell/App.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/save/SaveStore.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

namespace abalike::app::walk
{

inline const std::filesystem::path kSource = ABALIKE_SOURCE_DIR;

/// Frames per run on Earth: the reference shot leaves the slingshot at frame 30; 600 frames (10 s of game time)
/// reach the next bird's readiness, when the second shot flies, on every level whose first shot does not end it.
/// Weaker gravity flies and settles slower (framesFor).
inline constexpr int kEarthFrames = 600;
/// Every fourth frame is laid out (15 a second): the panels move with the camera, which moves smoothly.
inline constexpr int kLayoutEvery = 4;

/// Every campaign level (in play order) and every lesson.
inline std::vector<std::string> walkedLevels()
{
    std::vector<std::string> paths;
    const nlohmann::json manifest = nlohmann::json::parse(std::ifstream(kSource / "levels/campaign.json"));
    for (const nlohmann::json& episode : manifest.at("episodes"))
        for (const nlohmann::json& level : episode.at("levels"))
            paths.push_back((kSource / "levels" / level.get<std::string>()).string());
    std::vector<std::string> lessons;
    for (const auto& entry : std::filesystem::directory_iterator(kSource / "levels/lessons"))
        if (entry.path().extension() == ".json")
            lessons.push_back(entry.path().string());
    std::sort(lessons.begin(), lessons.end());
    paths.insert(paths.end(), lessons.begin(), lessons.end());
    return paths;
}

/// The test name of a walked level: its file's stem, made of letters, digits and underscores.
inline std::string walkedLevelName(const ::testing::TestParamInfo<std::string>& info)
{
    std::string name = std::filesystem::path(info.param).stem().string();
    std::replace_if(
        name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

class ScratchData
{
public:
    explicit ScratchData(const std::string& name = "layout")
        : m_path(std::filesystem::temp_directory_path() / ("abalike-" + name + "-" + std::to_string(::getpid())))
    {
        std::filesystem::create_directories(m_path);
    }
    ~ScratchData() { std::filesystem::remove_all(m_path); }
    ScratchData(const ScratchData&) = delete;
    ScratchData& operator=(const ScratchData&) = delete;
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

/// One window per size walked, kept open across runs: a new window is a new OpenGL context, whose start (the
/// software rasterizer compiling its shaders) would cost more than the run laid out in it.
inline sf::RenderWindow& windowOfSize(unsigned width, unsigned height)
{
    static std::map<std::pair<unsigned, unsigned>, std::unique_ptr<sf::RenderWindow>> windows;
    std::unique_ptr<sf::RenderWindow>& window = windows[{width, height}];
    if (!window)
    {
        window = std::make_unique<sf::RenderWindow>(sf::VideoMode(width, height), "abalike layout walk",
                                                    sf::Style::Titlebar | sf::Style::Close);
        window->setVerticalSyncEnabled(false);
        window->setKeyRepeatEnabled(true);
    }
    return *window;
}

/// Frames to walk a level: flights and settling last about 1/sqrt(g) as long as on Earth.
inline int framesFor(const LevelDef& level)
{
    const double slower = std::clamp(std::sqrt(9.81 / level.environment.gravity), 1.0, 3.0);
    const int frames = static_cast<int>(std::ceil(kEarthFrames * slower));
    return frames - frames % kLayoutEvery;
}

/// The reference shot, then the same again (as fast as the next bird can go) when the next bird is ready: aiming,
/// flight, the action after the first contact and the return to the slingshot.
inline std::vector<ScriptedShot> walkedShots(const LevelDef& level)
{
    const ScriptedShot first{level.referenceShot->angleDeg, level.referenceShot->speedMps};
    ScriptedShot second = first;
    if (level.birds.size() > 1)
        if (const BirdType* bird = Catalog::builtin().findBird(level.birds[1]))
            second.speedMps = std::min(second.speedMps, maxLaunchSpeed(level, *bird, Catalog::builtin()));
    return {first, second};
}

/// Plays one run in this process, in the kept window of its size, with the player's settings file as given (and no
/// other saved files), its trace in data's folder as trace.jsonl; returns the exit code.
inline int playLaidOut(AppOptions options, const nlohmann::json& settings, const ScratchData& data,
                       Campaign campaign = {})
{
    std::filesystem::remove(data.path() / "progress.json");
    std::ofstream(data.path() / "settings.json") << settings.dump();
    SaveStore store(data.path());
    store.load(SaveStore::Damaged::LeaveAlone);
    options.window = &windowOfSize(*options.width, *options.height);
    options.tracePath = (data.path() / "trace.jsonl").string();
    useGameScreens(options);
    App app(std::move(options), std::move(campaign), std::move(store), loadGameFont());
    return app.run();
}

} // namespace abalike::app::walk

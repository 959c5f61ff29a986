#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "cli/DataPaths.hpp"
#include "cli/WindowOptions.hpp"
#include "render/Font.hpp"
#include "screens/App.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/save/SaveStore.hpp>
#include <abalike/world/StressScenes.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace abalike::app
{

namespace
{

constexpr int kFrames = 600;     ///< 10 s of game time: the shot, the collapse, the settling
constexpr int kQuickFrames = 90; ///< the ctest smoke run
constexpr int kPreviewCalls = 300;
constexpr int kQuickPreviewCalls = 20;
constexpr unsigned kWidth = 1280;
constexpr unsigned kHeight = 720;
constexpr double kTargetP99Ms = 16.7;     ///< 60 frames per second
constexpr double kTargetPreviewMs = 0.17; ///< 1 % of a 60 Hz frame

/// One scene's measurement.
struct SceneFrames
{
    std::string name;
    std::size_t bodies = 0;
    std::vector<double> frameMs;
    double previewMedianMs = 0.0;
    long rssKb = -1;
};

volatile std::size_t g_sink = 0;

double percentile(std::vector<double> values, double fraction)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1) + 0.5);
    return values[std::min(index, values.size() - 1)];
}

/// The median cost of one RK4 preview of the shot (what the play screen computes when the aim changes: the
/// flight and its contact queries against the level), timed headless on the same level.
double previewMedianMs(const LevelDef& level, const ScriptedShot& shot, int calls)
{
    GameSession session(level);
    std::vector<double> ms;
    for (int i = 0; i < calls; ++i)
    {
        // A slightly different aim each call, as when the player drags: nothing can be cached between calls.
        const double angle = shot.angleDeg + 0.01 * (i % 7);
        const auto start = std::chrono::steady_clock::now();
        const PredictedFlight flight = session.preview(angle, shot.speedMps);
        const auto stop = std::chrono::steady_clock::now();
        g_sink = g_sink + flight.steps; // keeps the call from being optimised away
        ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    return percentile(ms, 0.5);
}

/// Plays the level in the real game loop (window, screens, every layer) with the shot fired at once.
/// path: the level's file (for "next level" in the campaign), empty for a scene held in memory.
SceneFrames playScene(const std::string& name, const std::string& path, const LevelDef& level, const ScriptedShot& shot,
                      int frames, Campaign campaign)
{
    SceneFrames result;
    result.name = name;
    result.bodies = level.blocks.size() + level.pigs.size();
    AppOptions options;
    options.levelPath = path;
    options.level = level;
    options.frames = frames;
    options.width = kWidth;
    options.height = kHeight;
    options.shots.push_back(shot);
    options.onFrameTimed = [&result](double frameS)
    {
        result.frameMs.push_back(1000.0 * frameS);
    };
    // Every overlay on, and the player's own files left alone: the settings come from a folder of our own (a
    // scripted run reads its data folder and never writes it).
    Settings settings;
    settings.teachingOverlay = true;
    settings.preview = PreviewMode::Full;
    settings.showActualPath = true;
    const std::filesystem::path dataDir =
        std::filesystem::temp_directory_path() / ("abalike-bench-frames-" + std::to_string(getpid()));
    std::filesystem::create_directories(dataDir);
    std::ofstream(dataDir / "settings.json") << settingsToJson(settings);
    SaveStore store(dataDir);
    store.load(SaveStore::Damaged::LeaveAlone);
    App app(std::move(options), std::move(campaign), std::move(store), loadGameFont());
    app.run();
    result.rssKb = residentKb();
    std::error_code ignored;
    std::filesystem::remove_all(dataDir, ignored);
    return result;
}

} // namespace

int runFramesBench(const BenchOptions& options)
{
    if (!haveDisplay())
        return 2;
    const int frames = options.quick ? kQuickFrames : kFrames;
    const int previewCalls = options.quick ? kQuickPreviewCalls : kPreviewCalls;
    const Campaign campaign = loadCampaignLevels(campaignManifest(), Catalog::builtin());

    // The campaign level with the most bodies, and its reference shot (or a flat full-power shot).
    const CampaignLevel* busiest = nullptr;
    for (const CampaignLevel& entry : campaign.levels)
        if (busiest == nullptr || entry.level.blocks.size() + entry.level.pigs.size() >
                                      busiest->level.blocks.size() + busiest->level.pigs.size())
            busiest = &entry;
    struct Scene
    {
        std::string name;
        std::string path;
        LevelDef level;
    };
    std::vector<Scene> scenes;
    if (busiest != nullptr)
        scenes.push_back({busiest->level.id, busiest->path, busiest->level});
    for (const StressScene& scene : structureScenes())
        if (scene.level.blocks.size() >= 1000)
        {
            scenes.push_back({scene.name, "", scene.level});
            break;
        }

    std::vector<SceneFrames> results;
    for (const Scene& scene : scenes)
    {
        const LevelDef& level = scene.level;
        GameSession probe(level);
        ScriptedShot shot(30.0, probe.maxLaunchSpeed());
        if (level.referenceShot)
            shot = ScriptedShot(level.referenceShot->angleDeg, level.referenceShot->speedMps);
        SceneFrames measured = playScene(scene.name, scene.path, level, shot, frames, campaign);
        measured.previewMedianMs = previewMedianMs(level, shot, previewCalls);
        results.push_back(std::move(measured));
    }

    ReportTable table({"scene", "bodies", "frames", "median ms", "p99 ms", "p99 target", "preview median ms",
                       "preview share", "preview target", "VmRSS MB"});
    for (const SceneFrames& scene : results)
    {
        const double median = percentile(scene.frameMs, 0.5);
        const double p99 = percentile(scene.frameMs, 0.99);
        table.addRow({scene.name, std::to_string(scene.bodies), std::to_string(scene.frameMs.size()),
                      formatSignificant(median), formatSignificant(p99),
                      p99 <= kTargetP99Ms ? "met (<= 16.7)" : "missed (> 16.7)",
                      formatSignificant(scene.previewMedianMs),
                      formatSignificant(median > 0.0 ? 100.0 * scene.previewMedianMs / median : 0.0) + " %",
                      scene.previewMedianMs <= kTargetPreviewMs ? "met (<= 0.17)" : "missed (> 0.17)",
                      formatSignificant(static_cast<double>(scene.rssKb) / 1024.0)});
    }
    std::ostringstream md;
    md << "# Frame times of the game loop\n\n"
       << "`abalike bench frames" << (options.quick ? " --quick" : "") << "`: " << frames << " frames at " << kWidth
       << "x" << kHeight << " per scene under the current display, the teaching overlay, preview and path on, the"
       << " scene's shot fired at once (one 1/60 s physics step per frame). Frame time: events, physics, every"
       << " layer, drawing and display, by the wall clock. Preview: one RK4 preview of the shot with its contact"
       << " queries, timed headless on the same level (median of " << previewCalls << "); its share is of the median"
       << " frame. Targets are reported, never asserted. " << loadAverageNote() << ".\n\n"
       << table.markdown();
    std::cout << "bench frames\n" << table.text();
    const bool written = writeReportFile(options.outDir, "frames.csv", table.csv()) &&
                         writeReportFile(options.outDir, "frames.md", md.str());
    return written && results.size() == scenes.size() && !scenes.empty() ? 0 : 1;
}

} // namespace abalike::app

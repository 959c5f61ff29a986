#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "editor/EditorScreen.hpp"
#include "render/Font.hpp"
#include "screens/GameScreens.hpp"
#include "shell/App.hpp"
#include "shell/AppContext.hpp"
#include "shell/DataPaths.hpp"
#include "shell/Display.hpp"
#include "teach/Guide.hpp"

#include <abalike/design/GeneratedLevelQueue.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/save/SaveStore.hpp>
#include <abalike/world/SettleCache.hpp>
#include <abalike/world/StressScenes.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>
#include <utility>

namespace abalike::app
{

namespace
{

constexpr int kFrames = 600;     ///< 10 s of game time: the shot, the collapse, the settling
constexpr int kQuickFrames = 90; ///< the ctest smoke run
constexpr int kPreviewCalls = 300;
constexpr int kQuickPreviewCalls = 20;
constexpr double kTargetPreviewMs = 0.17; ///< 1 % of a 60 Hz frame
constexpr std::size_t kSmallLevelBodies = 200;

/// A window size and what its frames must meet.
struct FrameSize
{
    unsigned width;
    unsigned height;
};
constexpr FrameSize kSmall{1280, 720};
constexpr FrameSize kLarge{1920, 1080};

/// One scene to play: a campaign level, a lesson or a stress scene.
struct Scene
{
    std::string name;
    std::string kind; ///< "level", "lesson" or "stress"
    std::string path; ///< the level's file; empty for a scene held in memory
    LevelDef level;
};

/// One scene's measurement at one window size.
struct SceneFrames
{
    std::string name;
    std::string kind;
    FrameSize size{};
    std::size_t bodies = 0;
    std::vector<FrameTimes> frames;
    double loadMs = 0.0;        ///< the first start: the settle step solved
    double settledLoadMs = 0.0; ///< a later start: the settled state read from SettleCache's file
    double previewMedianMs = 0.0;
    long rssKb = -1;
    bool generatorBusy = false; ///< a "generating" scene: the worker generated through every frame
};

/// The frame p99 target: 60 frames per second at 1280x720 except on the 1 000-block wall (40), 40 at 1920x1080;
/// the editor 30 frames a second (a designer's tool: every key and click still lands, see ImGuiInputQueue).
double targetP99Ms(const SceneFrames& scene)
{
    if (scene.kind == "editor")
        return 33.0;
    if (scene.kind == "generating")
        return 25.0; // the endless mode's worker generating the next level on the side (issue 40)
    return scene.size.width > kSmall.width || scene.kind == "stress" ? 25.0 : 16.7;
}

/// The campaign level the editor is timed on: the one whose body count is nearest 30, a designer's level.
const CampaignLevel* editorLevel(const Campaign& campaign)
{
    const CampaignLevel* best = nullptr;
    const auto distance = [](const CampaignLevel& l)
    {
        const auto bodies = static_cast<long>(l.level.blocks.size() + l.level.pigs.size());
        return std::abs(bodies - 30L);
    };
    for (const CampaignLevel& entry : campaign.levels)
        if (best == nullptr || distance(entry) < distance(*best))
            best = &entry;
    return best;
}

/// The load target: the first frame within 100 ms of choosing a level of up to 200 bodies, else within 1 s.
double targetLoadMs(const SceneFrames& scene)
{
    return scene.bodies <= kSmallLevelBodies ? 100.0 : 1000.0;
}

volatile std::size_t g_sink = 0;

double nearestRankPercentile(std::vector<double> values, double fraction)
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
    return nearestRankPercentile(ms, 0.5);
}

/// Keeps a scene's frame times; the first frame is the load (the settle step, the first glyphs and shaders),
/// counted as the load, not as a frame.
class SceneTimer final : public FrameObserver
{
public:
    explicit SceneTimer(SceneFrames& result) : m_result(result) {}
    void firstFrame(double loadS) override { m_result.loadMs = 1000.0 * loadS; }
    void frameTimed(const FrameTimes& times) override
    {
        if (!std::exchange(m_first, false))
            m_result.frames.push_back(times);
    }

private:
    SceneFrames& m_result;
    bool m_first = true;
};

/// Plays the level in the real game loop (window, screens, every layer) with the shot fired at once.
SceneFrames playScene(const Scene& scene, FrameSize size, const ScriptedShot& shot, int frames, Campaign campaign)
{
    SceneFrames result;
    result.name = scene.name;
    result.kind = scene.kind;
    result.size = size;
    result.bodies = scene.level.blocks.size() + scene.level.pigs.size();
    AppOptions options;
    options.levelPath = scene.path;
    options.level = scene.level;
    options.frames = frames;
    options.width = size.width;
    options.height = size.height;
    options.shots.push_back(shot);
    SceneTimer timer(result);
    options.observer = &timer;
    useGameScreens(options);
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
    if (scene.kind == "editor")
    {
        // The editor on the level: everything selected, then the pointer sweeping the scene (hover, rulers,
        // findings) every frame, as a designer's hand does.
        options.shots.clear();
        options.firstScreen = [level = scene.level](AppContext& app) -> std::unique_ptr<Screen>
        {
            EditorSource source;
            source.level = level;
            return std::make_unique<EditorScreen>(app, source);
        };
        ScriptEvent all;
        all.frame = 2;
        all.key = "A";
        all.ctrl = true;
        options.script.events.push_back(all);
        for (int f = 3; f <= frames; ++f)
        {
            ScriptEvent move;
            move.frame = f;
            move.kind = ScriptEvent::Kind::Mouse;
            move.action = ScriptEvent::Action::Move;
            move.x = 300 + (f * 7) % 600;
            move.y = 200 + (f * 5) % 400;
            options.script.events.push_back(move);
        }
        options.hasScript = true;
    }
    // The endless mode's worker, generating as it does while the player plays (low priority, one thread).
    std::unique_ptr<GeneratedLevelQueue> generating;
    if (scene.kind == "generating")
    {
        generating = std::make_unique<GeneratedLevelQueue>(
            [parts = loadGeneratorParts((std::filesystem::path(levelsDirectory()) / "parts").string(),
                                        Catalog::builtin())](const GeneratorOptions& o)
            { return generateLevel(parts, o, Catalog::builtin()); },
            GeneratorOptions{}, 4711);
        generating->want({5, 5});
    }
    App app(std::move(options), std::move(campaign), std::move(store), loadGameFont());
    app.run();
    if (generating)
    {
        // Started before the first frame: still at its first level at the end means it worked through every frame.
        const GeneratedLevelQueue::Status status = generating->status();
        result.generatorBusy = status.working && status.generated == 0;
    }
    result.rssKb = residentKb();
    std::error_code ignored;
    std::filesystem::remove_all(dataDir, ignored);
    return result;
}

/// The median of one part of the frame over every frame of a scene.
double partMedianMs(const SceneFrames& scene, double FrameTimes::*part)
{
    std::vector<double> ms;
    ms.reserve(scene.frames.size());
    for (const FrameTimes& times : scene.frames)
        ms.push_back(1000.0 * (times.*part));
    return nearestRankPercentile(std::move(ms), 0.5);
}

/// Every frame of every scene with its parts in ms, to find where a scene's slowest frames go.
std::string framePartsCsv(const std::vector<SceneFrames>& results)
{
    std::ostringstream csv;
    csv << "scene,window,frame,physics ms,preview ms,update ms,draw ms,display ms,total ms\n";
    for (const SceneFrames& scene : results)
        for (std::size_t i = 0; i < scene.frames.size(); ++i)
        {
            const FrameTimes& t = scene.frames[i];
            // Frames count from 1 and the first (the load) is not kept.
            csv << scene.name << ',' << scene.size.width << 'x' << scene.size.height << ',' << i + 2 << ','
                << 1000.0 * t.physicsS << ',' << 1000.0 * t.previewS << ',' << 1000.0 * t.updateS << ','
                << 1000.0 * t.drawS << ',' << 1000.0 * t.displayS << ',' << 1000.0 * t.totalS << '\n';
        }
    return csv.str();
}

/// Every campaign level in campaign order, every lesson, and the 1 000-block wall; with quick the busiest level, the
/// first lesson and the wall.
std::vector<Scene> framesScenes(const Campaign& campaign, bool quick)
{
    std::vector<Scene> scenes;
    const CampaignLevel* busiest = nullptr;
    for (const CampaignLevel& entry : campaign.levels)
    {
        if (!quick)
            scenes.push_back({entry.level.id, "level", entry.path, entry.level});
        if (busiest == nullptr || entry.level.blocks.size() + entry.level.pigs.size() >
                                      busiest->level.blocks.size() + busiest->level.pigs.size())
            busiest = &entry;
    }
    if (quick && busiest != nullptr)
        scenes.push_back({busiest->level.id, "level", busiest->path, busiest->level});
    const std::filesystem::path lessons = std::filesystem::path(campaign.manifestPath).parent_path() / "lessons";
    for (const LessonEntry& lesson : lessonList())
    {
        const std::string path = (lessons / lesson.file).string();
        scenes.push_back({lesson.id, "lesson", path, loadLevel(path, Catalog::builtin())});
        if (quick)
            break;
    }
    for (const StressScene& scene : structureScenes())
        if (scene.level.blocks.size() >= 1000)
        {
            scenes.push_back({scene.name, "stress", "", scene.level});
            break;
        }
    if (const CampaignLevel* level = editorLevel(campaign))
        scenes.push_back({"editor " + level->level.id, "editor", level->path, level->level});
    // The endless mode's first shipped castle, alone and while the worker generates the next level beside it.
    if (!quick)
    {
        const std::filesystem::path shipped = std::filesystem::path(levelsDirectory()) / "endless" / "101-0.3.json";
        if (std::filesystem::exists(shipped))
        {
            const LevelDef level = loadLevel(shipped.string(), Catalog::builtin());
            scenes.push_back({"endless-101", "level", shipped.string(), level});
            scenes.push_back({"endless-101 generating", "generating", shipped.string(), level});
        }
    }
    return scenes;
}

} // namespace

int runFramesBench(const BenchOptions& options)
{
    if (!haveDisplay())
        return 2;
    const int frames = options.quick ? kQuickFrames : kFrames;
    const int previewCalls = options.quick ? kQuickPreviewCalls : kPreviewCalls;
    const Campaign campaign = loadCampaignLevels(campaignManifest(), Catalog::builtin());
    std::vector<Scene> scenes = framesScenes(campaign, options.quick && options.scenes.empty());
    if (!options.scenes.empty())
    {
        // Only the scenes asked for, in the order asked; every one must exist.
        std::vector<Scene> chosen;
        for (const std::string& name : options.scenes)
        {
            const auto found =
                std::find_if(scenes.begin(), scenes.end(), [&name](const Scene& s) { return s.name == name; });
            if (found == scenes.end())
            {
                std::cerr << "bench frames: no scene \"" << name << "\" (expected a campaign level id such as 1-3, a "
                          << "lesson id such as lesson-angle, wall-20x50-mixed, or \"editor \" and a level id)\n";
                return 2;
            }
            chosen.push_back(*found);
        }
        scenes = std::move(chosen);
    }

    // The large window only where the screen holds it (Xvfb's screen is set on its command line).
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
    const bool largeFits = desktop.width >= kLarge.width && desktop.height >= kLarge.height;
    std::vector<SceneFrames> results;
    const std::filesystem::path settledDir =
        std::filesystem::temp_directory_path() / ("abalike-bench-frames-settled-" + std::to_string(getpid()));
    SettleCache& cache = SettleCache::shared();
    for (const Scene& scene : scenes)
    {
        GameSession probe(scene.level);
        ScriptedShot shot(30.0, probe.maxLaunchSpeed());
        if (scene.level.referenceShot)
            shot = ScriptedShot(scene.level.referenceShot->angleDeg, scene.level.referenceShot->speedMps);
        const double previewMs = previewMedianMs(scene.level, shot, previewCalls);
        std::vector<FrameSize> sizes{kSmall};
        if (!options.quick && largeFits && scene.kind != "stress" && scene.kind != "editor")
            sizes.push_back(kLarge);
        // Every size starts as the game's first start would (the settle step solved); the first one keeps the
        // settled state in a file, and one more frame-long start reads it back, as the game's next start would.
        const std::size_t first = results.size();
        for (const FrameSize size : sizes)
        {
            cache.setDirectory(size.width == sizes.front().width ? settledDir.string() : "", "bench frames");
            cache.clear();
            SceneFrames measured = playScene(scene, size, shot, frames, campaign);
            measured.previewMedianMs = previewMs;
            std::cerr << "bench frames: " << measured.name << " " << size.width << "x" << size.height << " done\n";
            results.push_back(std::move(measured));
        }
        cache.setDirectory(settledDir.string(), "bench frames");
        cache.clear();
        const double settledLoadMs =
            scene.kind == "editor" ? results[first].loadMs : playScene(scene, kSmall, shot, 1, campaign).loadMs;
        for (std::size_t i = first; i < results.size(); ++i)
            results[i].settledLoadMs = settledLoadMs;
    }
    cache.setDirectory("", "");
    cache.clear();
    std::error_code ignored;
    std::filesystem::remove_all(settledDir, ignored);

    ReportTable table({"scene", "kind", "window", "bodies", "first load ms", "load ms", "load target", "frames",
                       "median ms", "p99 ms", "p99 target", "physics ms", "update ms", "draw ms", "display ms",
                       "preview ms", "preview target", "VmRSS MB", "generating"});
    int missed = 0;
    for (const SceneFrames& scene : results)
    {
        std::vector<double> totalMs;
        for (const FrameTimes& times : scene.frames)
            totalMs.push_back(1000.0 * times.totalS);
        const double p99 = nearestRankPercentile(totalMs, 0.99);
        const double target = targetP99Ms(scene);
        const double loadTarget = targetLoadMs(scene);
        const auto verdict = [&missed](bool met, double limit)
        {
            missed += met ? 0 : 1;
            return std::string(met ? "met (<= " : "missed (> ") + formatSignificant(limit) + ")";
        };
        table.addRow(
            {scene.name, scene.kind, std::to_string(scene.size.width) + "x" + std::to_string(scene.size.height),
             std::to_string(scene.bodies), formatSignificant(scene.loadMs), formatSignificant(scene.settledLoadMs),
             verdict(scene.settledLoadMs <= loadTarget, loadTarget), std::to_string(scene.frames.size()),
             formatSignificant(nearestRankPercentile(totalMs, 0.5)), formatSignificant(p99),
             verdict(p99 <= target, target), formatSignificant(partMedianMs(scene, &FrameTimes::physicsS)),
             formatSignificant(partMedianMs(scene, &FrameTimes::updateS)),
             formatSignificant(partMedianMs(scene, &FrameTimes::drawS)),
             formatSignificant(partMedianMs(scene, &FrameTimes::displayS)), formatSignificant(scene.previewMedianMs),
             verdict(scene.previewMedianMs <= kTargetPreviewMs, kTargetPreviewMs),
             formatSignificant(static_cast<double>(scene.rssKb) / 1024.0),
             scene.kind != "generating" ? "-"
             : scene.generatorBusy      ? "every frame"
                                        : "part of the frames"});
    }
    std::ostringstream md;
    md << "# Frame times of the game loop\n\n"
       << "`abalike bench frames" << (options.quick ? " --quick" : "") << "`: " << frames
       << " frames per scene and window size (the first, the load, apart) under the current display, the teaching "
          "overlay, preview and path on,"
       << " the scene's shot fired at once (one 1/60 s physics step per frame)"
       << (largeFits || options.quick ? "" : "; the screen is smaller than 1920x1080, so that size was left out")
       << ". Load: from choosing the level to its first frame shown, the first time (first load: the settle step "
          "solved, as on the game's first start with that level) and when it was settled before (load: the settled "
          "state read from the file the first start left, as on every later start; the target's measure). Frame "
          "time: events,"
       << " physics, every layer, drawing and display, by the wall clock, and the median of each part (physics: the"
       << " fixed steps; update: events, camera and layers; draw: building and submitting the layers; display:"
       << " showing the frame, where software GL fills the pixels). Preview: one RK4 preview of the shot with its"
       << " contact queries, timed headless on the same level (median of " << previewCalls
       << "). Targets are reported, never asserted: " << missed << " missed. " << loadAverageNote() << ".\n\n"
       << table.markdown();
    std::cout << "bench frames\n" << table.text() << missed << " targets missed\n";
    const bool written = writeReportFile(options.outDir, "frames.csv", table.csv()) &&
                         writeReportFile(options.outDir, "frames.md", md.str()) &&
                         writeReportFile(options.outDir, "frame-parts.csv", framePartsCsv(results));
    return written && !results.empty() ? 0 : 1;
}

} // namespace abalike::app

#include "screens/EndlessNavigation.hpp"

#include "endless/EndlessGame.hpp"
#include "screens/EndlessWaitScreen.hpp"
#include "screens/Navigation.hpp"
#include "screens/PlayScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/Trace.hpp"

namespace abalike::app
{

std::unique_ptr<Screen> endlessLevelScreen(AppContext& app)
{
    EndlessGame& endless = app.progress().endless();
    if (endless.playing())
    {
        // The player left the last castle unfinished (to the title, level select): the run ends as with a loss.
        const EndlessRun::Result run = endless.lost();
        app.trace().write("endless-left", {{"levels_won", run.levelsWon}, {"score", run.score}});
        app.progress().recordEndless(run.levelsWon, run.score, true);
    }
    if (std::optional<EndlessLevel> level = endless.nextLevel())
    {
        app.trace().write("endless-level", {{"seed", level->seed},
                                            {"loss_share", level->lossShareTenths / 10.0},
                                            {"generated", level->generatedName()},
                                            {"shipped", level->shipped},
                                            {"run_levels_won", endless.run().levelsWon()},
                                            {"run_score", endless.run().score()}});
        PlaySource source{level->level, "", std::nullopt, PlayMode::Game};
        source.endless = std::move(level);
        return std::make_unique<PlayScreen>(app, std::move(source));
    }
    return nullptr;
}

std::unique_ptr<Screen> nextEndlessScreen(AppContext& app)
{
    if (std::unique_ptr<Screen> level = endlessLevelScreen(app))
        return level;
    return std::make_unique<EndlessWaitScreen>(app);
}

void playNextEndlessLevel(AppContext& app)
{
    openTitle(app);
    app.navigator().screens().push(nextEndlessScreen(app));
}

} // namespace abalike::app

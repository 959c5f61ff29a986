#pragma once

#include <abalike/flight/Prediction.hpp>
#include <abalike/game/Score.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <abalike/teach/FlightEnergy.hpp>
#include <abalike/world/GameWorld.hpp>
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace abalike
{

/// Where a level is in its life.
enum class Phase
{
    Aiming, ///< a bird waits in the slingshot (the world may still move)
    Flying, ///< a shot is under way; the next bird waits until it is ready (GameSession::kReadyAfterContactS)
    Won,    ///< no pig left (after at most kWinGraceS of grace)
    Lost,   ///< birds used up, pigs left, world calm (or the time limit ran out)
};

/// What happened to one shot: the prediction made at launch and what the world did.
struct ShotRecord
{
    std::string bird;
    double angleDeg = 0.0;
    double speedMps = 0.0;
    BandPull pull; ///< the slingshot's pull that gave the launch (the smallest for speedMps)
    std::optional<ContactPoint> predictedContact;
    std::optional<ContactPoint> actualContact;
    /// Distance between predicted and actual first contact; only when the bird flew the predicted flight, i.e.
    /// no ability changed it before its first contact (a split does not: the bird flies on unchanged).
    std::optional<double> deviationM;
    std::optional<EntityKind> firstTouched; ///< what the bird first touched
    std::vector<TrackPoint> predictedPath;
    std::vector<TrackPoint> actualPath;
    std::vector<std::vector<BodyRef>> actualTouches; ///< beside each actualPath point: what the bird touched
    std::optional<AbilityUse> ability; ///< the ability, if used: when, where, and every impulse it applied
    /// The energy balance at the first contact, along the RK4 flight the bird flew; none when an ability fired
    /// before the first contact or the bird touched nothing.
    std::optional<FlightEnergy> energy;
    std::optional<FirstImpact> impact; ///< the first contact, when it was with a block or a pig
    int pigsDefeated = 0;              ///< pigs defeated while this shot was under way
    /// The air or gravity changed while it flew (the sandbox): the prediction made at launch no longer applies.
    bool environmentChanged = false;
    /// Something still moved when it was launched (GameWorld::isCalm): the preview was cast against the bodies
    /// where they were then, so it gets no deviation and no accuracy points.
    bool launchedIntoMovingWorld = false;
    /// World time of the shot's first contact (its bird or a split bird touching anything); none if it touched
    /// nothing.
    std::optional<double> contactTimeS;
    /// Seconds from the first contact until the next bird was ready or the level ended.
    std::optional<double> readyAfterContactS;
    int accuracyPoints = 0; ///< this shot's share of ScoreBreakdown::accuracyBonus
};

/// A scripted shot: angle in degrees, launch speed in m/s, and when (s after launch) to use the bird's ability.
struct ScriptedShot
{
    ScriptedShot() = default;
    ScriptedShot(double angle, double speed, std::optional<double> abilityAt = std::nullopt)
        : angleDeg(angle), speedMps(speed), abilityAtS(abilityAt)
    {
    }

    double angleDeg = 0.0;
    double speedMps = 0.0;
    std::optional<double> abilityAtS; ///< none: the ability is not used
};

/// A launch the rules do not allow (no bird, not aiming, too fast); the message says why.
class LaunchError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/// One play of one level: the rules around a GameWorld. Headless; the game and the CLI both drive it.
class GameSession
{
public:
    explicit GameSession(LevelDef level, const Catalog& catalog = Catalog::builtin(), WorldSettings settings = {});

    /// The next bird is ready at the latest this long after the shot's first contact, even if the world still moves.
    static constexpr double kReadyAfterContactS = 3.0;
    /// A bird that touched nothing and has left the world: the next is ready at the latest this long after.
    static constexpr double kReadyAfterBirdsGoneS = 1.0;
    /// When the last pig falls the level is won after at most this long (more may still break for points).
    static constexpr double kWinGraceS = 1.0;
    /// Longest a shot lasts with the last bird before the level is lost, even if something still moves.
    static constexpr double kShotTimeCapS = 20.0;

    /// Starts the level again from its definition.
    void restart();
    /// One fixed physics step.
    void step();

    Phase phase() const { return m_phase; }
    bool finished() const { return m_phase == Phase::Won || m_phase == Phase::Lost; }
    /// Why a lost level was lost: its time limit ran out with a pig standing (true), or the birds ran out (false).
    bool outOfTime() const { return m_outOfTime; }
    /// "won", "out_of_birds" or "out_of_time" once finished (the trace's reason), else "".
    const char* endReason() const
    {
        return m_phase == Phase::Won    ? "won"
               : m_phase != Phase::Lost ? ""
               : m_outOfTime            ? "out_of_time"
                                        : "out_of_birds";
    }
    /// No pig is left: the level is won once the grace ends (kWinGraceS); no bird can be launched meanwhile.
    bool winPending() const { return m_winSinceS.has_value() && !finished(); }

    /// The bird in (or next for) the slingshot; nullptr when none is left.
    const BirdType* currentBird() const;
    int birdsUsed() const { return m_nextBird; }
    int birdsRemaining() const;
    int pigsRemaining() const { return m_world->pigsAlive(); }

    /// The slingshot's band launching the current bird (pull, force, stored energy, launch speed); none when no
    /// bird is left.
    std::optional<SlingshotBand> band() const;
    /// Fastest launch of the current bird: a full pull, at most the catalog's launch-speed cap.
    double maxLaunchSpeed() const;
    /// Where a bird leaves the slingshot.
    Vec2 launchPoint() const;

    /// The flight model acting on a bird in this level (gravity, drag from air density, wind).
    FlightModel flightModelFor(const BirdType& bird) const;
    /// RK4 preview of a launch of the current bird, up to its first contact with level geometry.
    PredictedFlight preview(double angleDeg, double speedMps) const;
    /// Launches the current bird. Throws LaunchError when not aiming or faster than the bird can be launched.
    void launch(double angleDeg, double speedMps);
    /// Launches the current bird as a scripted shot says; also throws LaunchError when the shot asks for an
    /// ability the bird does not have, or at a time that is not a number of seconds >= 0.
    void launch(const ScriptedShot& shot);
    /// Changes gravity, air and wind now, even mid-flight (the sandbox's live environment). A shot in the air is
    /// marked environmentChanged and gets no deviation or accuracy points; later previews use the new air.
    void setEnvironment(const EnvironmentDef& environment);
    /// Changes the level's custom bird for the birds not yet launched (the sandbox's bird panel).
    void setCustomBird(const CustomBirdDef& bird);
    /// Whether the flying bird's ability can be used now (see GameWorld::canActivateAbility).
    bool canActivateAbility() const;
    /// Uses the flying bird's ability (click or Space in flight); false if it cannot be used now.
    bool activateAbility();
    /// Time since the current shot was launched (s).
    double timeSinceLaunch() const { return m_world->time() - m_shotStartTime; }

    const std::vector<ShotRecord>& shots() const { return m_shots; }
    /// Everything destroyed since the level (re)started, in order (the game's particles and score pop-ups), with
    /// birds that retired (kind Bird).
    const std::vector<DestroyedEvent>& destroyed() const { return m_destroyed; }
    /// Blocks broken and pigs defeated since the level (re)started, in order, with their causes.
    std::vector<DestroyedEvent> defeats() const;
    /// TNT blasts since the level (re)started, in order.
    const std::vector<BlastEvent>& blasts() const { return m_blasts; }
    ScoreBreakdown score() const { return m_score; }
    int stars() const;
    double simTime() const { return m_world->time(); }

    /// A message for the player when the session had to act on its own (e.g. reset after a non-finite body state);
    /// empty otherwise. clearNotice() once it has been shown.
    const std::string& notice() const { return m_notice; }
    void clearNotice() { m_notice.clear(); }

    const LevelDef& level() const { return m_level; }
    const GameWorld& world() const { return *m_world; }
    /// The catalog as this level sees it (its material overrides and custom bird applied, see levelCatalog).
    const Catalog& catalog() const { return m_catalog; }

private:
    void collectEvents();
    void updateBird();
    void updatePhase();
    /// The shot under way is over: the next bird is ready or the level ended.
    void endTurn(Phase next);

    LevelDef m_level;
    Catalog m_catalog;
    WorldSettings m_settings;
    std::unique_ptr<GameWorld> m_world;
    Phase m_phase = Phase::Aiming;
    bool m_outOfTime = false;
    int m_nextBird = 0;
    double m_shotStartTime = 0.0;
    std::vector<ShotRecord> m_shots;
    std::vector<DestroyedEvent> m_destroyed;
    std::vector<BlastEvent> m_blasts;
    std::optional<double> m_winSinceS;    ///< when the last pig fell
    std::optional<double> m_birdsGoneAtS; ///< when the shot's birds had all left without touching anything
    std::string m_notice;
    ScoreBreakdown m_score;
};

/// Plays the shots in order, headless, each as soon as its bird is ready, through the ShotSequence that `play --shot`
/// drives too (so the window replays it exactly: docs/cli.md); returns the session once the shots are played out.
/// Throws LaunchError if a shot cannot be fired (more shots than birds, too fast).
std::unique_ptr<GameSession> simulateShots(const LevelDef& level, const std::vector<ScriptedShot>& shots,
                                           const Catalog& catalog = Catalog::builtin());

} // namespace abalike

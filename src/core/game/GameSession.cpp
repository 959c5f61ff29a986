#include <abalike/game/GameSession.hpp>
#include <abalike/game/ShotSequence.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <sstream>

namespace abalike
{

GameSession::GameSession(LevelDef level, const Catalog& catalog, WorldSettings settings)
    : m_level(std::move(level)), m_catalog(levelCatalog(m_level, catalog)), m_settings(settings)
{
    for (const std::string& name : m_level.birds)
        if (m_catalog.findBird(name) == nullptr)
            throw std::invalid_argument("unknown bird \"" + name + "\"");
    restart();
}

void GameSession::restart()
{
    m_world = std::make_unique<GameWorld>(m_level, m_catalog, m_settings);
    m_phase = Phase::Aiming;
    m_outOfTime = false;
    m_nextBird = 0;
    m_shotStartTime = 0.0;
    m_shots.clear();
    m_destroyed.clear();
    m_blasts.clear();
    m_winSinceS.reset();
    m_birdsGoneAtS.reset();
    m_score = {};
}

const BirdType* GameSession::currentBird() const
{
    if (m_nextBird >= static_cast<int>(m_level.birds.size()))
        return nullptr;
    return m_catalog.findBird(m_level.birds[static_cast<std::size_t>(m_nextBird)]);
}

int GameSession::birdsRemaining() const
{
    return static_cast<int>(m_level.birds.size()) - m_nextBird;
}

std::optional<SlingshotBand> GameSession::band() const
{
    const BirdType* bird = currentBird();
    if (bird == nullptr)
        return std::nullopt;
    return slingshotBand(m_level, *bird, m_catalog);
}

double GameSession::maxLaunchSpeed() const
{
    const BirdType* bird = currentBird();
    return bird == nullptr ? 0.0 : abalike::maxLaunchSpeed(m_level, *bird, m_catalog);
}

Vec2 GameSession::launchPoint() const
{
    return {m_level.slingshot.x, m_level.slingshot.y};
}

FlightModel GameSession::flightModelFor(const BirdType& bird) const
{
    return levelFlightModel(m_level.environment, bird); // the one definition the level checks use too
}

PredictedFlight GameSession::preview(double angleDeg, double speedMps) const
{
    const BirdType* bird = currentBird();
    if (bird == nullptr)
        return {};
    IntegratorSettings settings;
    settings.dtS = m_settings.dtS;
    PredictionLimits limits;
    limits.maxTimeS = 15.0;
    // The preview casts the circle the world collides with (a tiny custom bird collides as a larger one).
    const double radius = m_world->birdBody(*bird).radiusM;
    limits.contact = [this, radius](const FlightState& a, const FlightState& b)
    {
        return m_world->castCircle(radius, a, b);
    };
    const auto p = launchPoint();
    return predictFlight(flightModelFor(*bird), settings, launchState(p.x, p.y, speedMps, angleDeg), limits);
}

void GameSession::launch(double angleDeg, double speedMps)
{
    const BirdType* bird = currentBird();
    std::ostringstream why;
    if (finished())
        why << "the level is over";
    else if (bird == nullptr)
        why << "no bird left to launch (the level has " << m_level.birds.size() << ")";
    else if (winPending())
        why << "no pig is left: the level is won";
    else if (m_phase != Phase::Aiming)
        why << "a shot is still under way";
    else if (!std::isfinite(angleDeg) || !std::isfinite(speedMps))
        why << "angle and speed must be finite numbers";
    else if (angleDeg < -90.0 || angleDeg > 90.0)
        why << "angle " << angleDeg << " deg is outside -90 to 90";
    else if (speedMps < 0.0)
        why << "speed must be >= 0 m/s, got " << speedMps;
    else if (speedMps > maxLaunchSpeed() * (1.0 + 1e-12))
        why << "bird " << m_nextBird + 1 << " (" << bird->name << ", " << bird->massKg
            << " kg) can be launched at most " << maxLaunchSpeed() << " m/s (slingshot " << band()->maxForceN()
            << " N at a " << band()->maxPullM() << " m pull, band mass " << band()->bandMassKg() << " kg), asked "
            << speedMps << " m/s";
    if (!why.str().empty())
        throw LaunchError(why.str());

    ShotRecord shot;
    shot.bird = bird->name;
    shot.angleDeg = angleDeg;
    shot.speedMps = speedMps;
    shot.pull = band()->forSpeed(speedMps);
    shot.launchedIntoMovingWorld = !m_world->isCalm();
    const PredictedFlight predicted = preview(angleDeg, speedMps);
    shot.predictedContact = predicted.contact;
    for (const PathPoint& point : predicted.path)
        shot.predictedPath.push_back({point.timeS, point.state.position});
    const auto p = launchPoint();
    m_world->launchBird(*bird, flightModelFor(*bird), launchState(p.x, p.y, speedMps, angleDeg));
    shot.actualPath = m_world->birdPath();
    shot.actualTouches = m_world->birdPathTouches();
    m_shots.push_back(std::move(shot));
    ++m_nextBird;
    m_phase = Phase::Flying;
    m_shotStartTime = m_world->time();
    m_birdsGoneAtS.reset();
}

void GameSession::setEnvironment(const EnvironmentDef& environment)
{
    if (environment == m_level.environment)
        return;
    m_level.environment = environment;
    m_world->setEnvironment(environment);
    if (m_phase == Phase::Flying && !m_shots.empty() && !m_shots.back().actualContact)
        m_shots.back().environmentChanged = true;
}

void GameSession::setCustomBird(const CustomBirdDef& bird)
{
    m_level.customBird = bird;
    m_catalog.putBird(customBirdType(bird)); // the flying bird keeps its own copy of the type
}

bool GameSession::canActivateAbility() const
{
    return m_phase == Phase::Flying && m_world->canActivateAbility();
}

bool GameSession::activateAbility()
{
    if (!canActivateAbility() || m_shots.empty())
        return false;
    std::optional<AbilityUse> use = m_world->activateAbility();
    if (!use)
        return false;
    m_shots.back().ability = std::move(use);
    collectEvents(); // a blast may have destroyed something already
    return true;
}

void GameSession::step()
{
    if (finished())
        return;
    m_world->step();
    if (m_world->hasNonFiniteState())
    {
        // Box2D let a body escape to NaN or infinity: nothing after this step can be trusted, so start over.
        restart();
        m_notice = "The simulation produced an invalid number, so the level was reset.";
        return;
    }
    // The black bird's fuse: an ability the player never used went off by itself in that step.
    if (std::optional<AbilityUse> fused = m_world->takeFusedAbility(); fused && !m_shots.empty())
        m_shots.back().ability = std::move(fused);
    collectEvents();
    updateBird();
    updatePhase();
}

void GameSession::collectEvents()
{
    ShotRecord* shot = m_shots.empty() ? nullptr : &m_shots.back();
    for (const BlastEvent& blast : m_world->takeBlastEvents())
        m_blasts.push_back(blast);
    for (DestroyedEvent event : m_world->takeDestroyedEvents())
    {
        event.shot = static_cast<int>(m_shots.size()) - 1;
        m_destroyed.push_back(event);
        if (event.kind == EntityKind::Block && event.points > 0)
        {
            m_score.blockPoints += event.points;
            ++m_score.blocksDestroyed;
        }
        else if (event.kind == EntityKind::Pig)
        {
            m_score.pigPoints += event.points;
            ++m_score.pigsDefeated;
            if (shot == nullptr)
                continue;
            // Efficiency: one bird doing the work of two.
            if (++shot->pigsDefeated > 1)
                m_score.efficiencyBonus += m_catalog.scoring().efficiencyPointsPerExtraPig;
        }
    }
}

void GameSession::updateBird()
{
    const Entity* bird = m_world->bird();
    if (bird == nullptr || m_shots.empty())
        return;
    ShotRecord& shot = m_shots.back();
    // Keep the record's actual path in step with the world's, one point per step.
    const auto& path = m_world->birdPath();
    for (std::size_t i = shot.actualPath.size(); i < path.size(); ++i)
        shot.actualPath.push_back(path[i]);
    const auto& touches = m_world->birdPathTouches();
    for (std::size_t i = shot.actualTouches.size(); i < touches.size(); ++i)
        shot.actualTouches.push_back(touches[i]);
    if (shot.actualContact || !m_world->birdContact())
        return;
    shot.actualContact = m_world->birdContact();
    shot.firstTouched = m_world->birdContactKind();
    shot.impact = m_world->birdImpact();
    if (!(shot.ability && shot.ability->beforeContact))
    {
        // The world flew the bird along exactly this RK4 flight until the contact: replay it for its energy.
        const BirdType& bird = *m_catalog.findBird(shot.bird);
        const auto p = launchPoint();
        IntegratorSettings settings;
        settings.dtS = m_settings.dtS;
        shot.energy = flightEnergyAt(flightModelFor(bird), settings,
                                     launchState(p.x, p.y, shot.speedMps, shot.angleDeg), shot.actualContact->t);
    }
    // The prediction made at launch is only a claim about the flight that was launched: once an ability changed
    // that flight, the distance between the two contacts measures the ability, not the prediction.
    const bool flightChanged =
        (shot.ability && shot.ability->changedFlight) || shot.environmentChanged || shot.launchedIntoMovingWorld;
    if (!shot.predictedContact || flightChanged)
        return;
    shot.deviationM =
        std::hypot(shot.actualContact->x - shot.predictedContact->x, shot.actualContact->y - shot.predictedContact->y);
    // Accuracy counts where the bird meets the structure (a block or a pig), not the ground.
    if (shot.firstTouched == EntityKind::Block || shot.firstTouched == EntityKind::Pig)
    {
        const ScoringRules& rules = m_catalog.scoring();
        shot.accuracyPoints =
            accuracyPointsFor(*shot.deviationM, rules.accuracyPointsPerShot, rules.accuracyToleranceM);
        m_score.accuracyBonus += shot.accuracyPoints;
        if (shot.accuracyPoints > 0)
            ++m_score.accurateShots;
    }
}

void GameSession::updatePhase()
{
    // A time-limited level is lost the moment its clock runs out with a pig still standing, whatever is flying.
    if (m_level.timeLimitS && !finished() && m_world->time() >= *m_level.timeLimitS && m_world->pigsAlive() > 0)
    {
        m_outOfTime = true;
        endTurn(Phase::Lost);
        return;
    }
    const double now = m_world->time();
    if (m_phase == Phase::Flying && !m_shots.empty() && !m_shots.back().contactTimeS)
        m_shots.back().contactTimeS = m_world->shotContactTime();
    const bool calm = !m_world->birdsInPlay() && m_world->isCalm();
    // Won as soon as no pig is left, after a short grace in which more may still break (a sandbox scene without
    // pigs is never won: it is played until its birds are used up).
    if (!m_level.pigs.empty() && m_world->pigsAlive() == 0)
    {
        if (!m_winSinceS)
            m_winSinceS = now;
        if (calm || now - *m_winSinceS >= kWinGraceS - 1e-9)
        {
            m_score.unusedBirds = birdsRemaining();
            m_score.unusedBirdBonus = birdsRemaining() * m_catalog.pointsPerUnusedBird();
            endTurn(Phase::Won);
        }
        return;
    }
    if (m_phase != Phase::Flying)
        return;
    const std::optional<double>& contact = m_shots.back().contactTimeS;
    if (!contact && !m_world->birdsInPlay() && !m_birdsGoneAtS)
        m_birdsGoneAtS = now; // the shot touched nothing and its birds are gone
    const bool timeUp = now - m_shotStartTime >= kShotTimeCapS - 1e-9;
    if (birdsRemaining() == 0)
    {
        // The last bird: a falling structure may still take a pig, so the level is lost only once all is calm.
        if (calm || timeUp)
            endTurn(Phase::Lost);
        return;
    }
    const bool soonAfterContact = contact && now - *contact >= kReadyAfterContactS - 1e-9;
    const bool soonAfterGone = m_birdsGoneAtS && now - *m_birdsGoneAtS >= kReadyAfterBirdsGoneS - 1e-9;
    if (calm || soonAfterContact || soonAfterGone || timeUp)
        endTurn(Phase::Aiming);
}

void GameSession::endTurn(Phase next)
{
    if (m_phase == Phase::Flying && !m_shots.empty())
    {
        ShotRecord& shot = m_shots.back();
        if (!shot.contactTimeS)
            shot.contactTimeS = m_world->shotContactTime();
        if (shot.contactTimeS)
            shot.readyAfterContactS = m_world->time() - *shot.contactTimeS;
    }
    // The shot's birds leave with a puff; what they set moving goes on moving.
    m_world->retireAllBirds();
    collectEvents();
    m_phase = next;
}

std::vector<DestroyedEvent> GameSession::defeats() const
{
    std::vector<DestroyedEvent> defeats;
    for (const DestroyedEvent& event : m_destroyed)
        if (event.kind == EntityKind::Block || event.kind == EntityKind::Pig)
            defeats.push_back(event);
    return defeats;
}

int GameSession::stars() const
{
    return starsFor(m_score.total(), m_phase == Phase::Won, m_level.starScores);
}

void GameSession::launch(const ScriptedShot& shot)
{
    if (const auto at = shot.abilityAtS)
    {
        const BirdType* bird = currentBird();
        if (!std::isfinite(*at) || *at < 0.0)
            throw LaunchError("the ability time must be a finite number of seconds >= 0");
        if (bird != nullptr && !bird->ability)
            throw LaunchError("bird " + std::to_string(birdsUsed() + 1) + " (" + bird->name +
                              ") has no ability to use");
    }
    launch(shot.angleDeg, shot.speedMps);
}

std::unique_ptr<GameSession> simulateShots(const LevelDef& level, const std::vector<ScriptedShot>& shots,
                                           const Catalog& catalog)
{
    if (shots.size() > level.birds.size())
        throw LaunchError("shot " + std::to_string(level.birds.size() + 1) +
                          ": no bird left to launch (the level has " + std::to_string(level.birds.size()) + ")");
    auto session = std::make_unique<GameSession>(level, catalog);
    ShotSequence sequence(shots);
    while (sequence.advance(*session, session->world().dt()) != ShotSequence::Tick::Idle)
    {
    }
    return session;
}

} // namespace abalike

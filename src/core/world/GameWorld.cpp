#include "world/BirdFlight.hpp"
#include "world/Damage.hpp"
#include "world/ImpactRecorder.hpp"
#include "world/SettleStep.hpp"
#include "world/WorldBodies.hpp"
#include "world/WorldStepper.hpp"

#include <abalike/world/GameWorld.hpp>
#include <cmath>
#include <stdexcept>

namespace abalike
{

namespace
{

const WorldSettings& checked(const WorldSettings& settings)
{
    if (!(settings.dtS > 0.0) || !std::isfinite(settings.dtS))
        throw std::invalid_argument("world time step must be a finite number > 0");
    if (settings.velocityIterations < 1 || settings.positionIterations < 0 || settings.maxSubsteps < 1 ||
        settings.stackDepthPerSubstep < 1 || settings.maxStackSubsteps < 1)
        throw std::invalid_argument("world iterations and sub-steps must be >= 1");
    if (!(settings.cornerChamferM >= 0.0 && settings.cornerChamferM < 0.02) || !std::isfinite(settings.contactGapM))
        throw std::invalid_argument("corner chamfer must be 0 to 2 cm and the contact gap finite");
    return settings;
}

} // namespace

GameWorld::GameWorld(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings)
    : m_bodies(std::make_unique<WorldBodies>(level, catalog, checked(settings)))
{
    m_bodies->build();
    m_stepper = std::make_unique<WorldStepper>(*m_bodies);
    m_settle = std::make_unique<SettleStep>(*m_bodies, *m_stepper);
    m_impacts = std::make_unique<ImpactRecorder>(*m_bodies);
    m_damage = std::make_unique<Damage>(*m_bodies);
    m_birds = std::make_unique<BirdFlight>(*m_bodies, *m_impacts);
}

GameWorld::~GameWorld() = default;

void GameWorld::step()
{
    m_bodies->contacts().clearStep();
    const Vec2 birdStart = m_birds->beforeStep();
    // The ledger and the snapshot only while the bird flies free: its next contact may be its first impact.
    m_bodies->contacts().ledger().startStep(m_birds->inFreeFlight());
    if (m_birds->inFreeFlight())
        m_impacts->snapshot();
    const bool settle = m_steps == 0;
    m_stepper->planStep(settle);
    if (!settle || !m_settle->run(m_birds->inPlay()))
        m_stepper->stepBox2d(settle);
    ++m_steps;
    m_bodies->world().ClearForces();
    m_bodies->tick();

    m_birds->afterStep(birdStart);
    m_damage->releaseSlowBullets();
    m_damage->applyStep(m_impacts->pendingEntity());
    m_impacts->finishStep(m_damage->watchedRefund(), m_damage->watchedHandedOn(), m_birds->birdIndex());
    removeOutOfBounds();
    m_birds->updateRest();
    fuseAbility();
    m_birds->retire();
    m_stepper->updateCalm();
}

void GameWorld::removeOutOfBounds()
{
    for (std::size_t i = 0; i < m_bodies->entities().size(); ++i)
    {
        const Entity& e = m_bodies->entities()[i];
        if (!m_bodies->outOfBounds(e))
            continue;
        const int index = static_cast<int>(i);
        if (index == m_birds->birdIndex())
            m_birds->removeBird();
        else if (e.kind == EntityKind::Bird)
            m_birds->removeProjectileOf(index);
        else
            // A pig off the world is defeated; a block off it is gone but not broken.
            m_bodies->destroyEntity(index, e.kind == EntityKind::Pig, {CauseKind::OutOfBounds, -1});
    }
}

double GameWorld::time() const
{
    return m_bodies->time();
}

double GameWorld::dt() const
{
    return m_bodies->settings().dtS;
}

const WorldSettings& GameWorld::settings() const
{
    return m_bodies->settings();
}

int GameWorld::lastSubsteps() const
{
    return m_stepper->lastSubsteps();
}

int GameWorld::stackSubsteps() const
{
    return m_stepper->stackSubsteps();
}

int GameWorld::restingStackSubsteps() const
{
    return m_stepper->restingStackSubsteps();
}

int GameWorld::substepsFor(double speedMps) const
{
    return m_stepper->substepsFor(speedMps);
}

double GameWorld::maxSpeedMps() const
{
    return m_stepper->maxSpeedMps();
}

int GameWorld::stackDepth() const
{
    return m_stepper->stackDepth();
}

int GameWorld::settleIterations() const
{
    return m_stepper->settleIterations();
}

int GameWorld::settleSubstepsDone() const
{
    return m_stepper->settleSubstepsDone();
}

int GameWorld::settleSubstepsPlanned() const
{
    return m_stepper->stackSubsteps();
}

bool GameWorld::settleReused() const
{
    return m_settle->reused();
}

void GameWorld::setEnvironment(const EnvironmentDef& environment)
{
    m_bodies->level().environment = environment;
    m_bodies->world().SetGravity(b2Vec2(0.0f, static_cast<float>(-environment.gravity)));
    m_birds->setEnvironment(environment);
}

BirdBody GameWorld::birdBody(const BirdType& bird) const
{
    return m_birds->birdBody(bird);
}

int GameWorld::launchBird(const BirdType& bird, const FlightModel& model, const FlightState& s0)
{
    return m_birds->launch(bird, model, s0);
}

void GameWorld::removeBird()
{
    m_birds->removeBird();
}

void GameWorld::removeAllBirds()
{
    m_birds->removeAllBirds();
}

const Entity* GameWorld::bird() const
{
    const int index = m_birds->birdIndex();
    return index >= 0 ? &m_bodies->entity(index) : nullptr;
}

int GameWorld::projectilesInPlay() const
{
    return m_birds->projectilesInPlay();
}

bool GameWorld::birdInFreeFlight() const
{
    return m_birds->inFreeFlight();
}

const std::optional<ContactPoint>& GameWorld::birdContact() const
{
    return m_birds->contact();
}

const std::optional<EntityKind>& GameWorld::birdContactKind() const
{
    return m_birds->contactKind();
}

const std::optional<FirstImpact>& GameWorld::birdImpact() const
{
    return m_impacts->impact();
}

const std::vector<TrackPoint>& GameWorld::birdPath() const
{
    return m_birds->path();
}

const std::vector<std::vector<BodyRef>>& GameWorld::birdPathTouches() const
{
    return m_birds->pathTouches();
}

std::optional<double> GameWorld::castCircle(double radiusM, const FlightState& a, const FlightState& b) const
{
    const double chordM = std::hypot(b.position.x - a.position.x, b.position.y - a.position.y);
    return m_bodies->castCircle(radiusM, a, b, m_stepper->substepsFor(chordM / m_bodies->settings().dtS));
}

bool GameWorld::isSettled() const
{
    return m_bodies->isSettled();
}

bool GameWorld::isCalm() const
{
    return m_stepper->isCalm();
}

const std::optional<double>& GameWorld::shotContactTime() const
{
    return m_birds->shotContactTime();
}

bool GameWorld::birdsInPlay() const
{
    return m_birds->inPlay();
}

void GameWorld::retireAllBirds()
{
    m_birds->retireAll();
}

int GameWorld::pigsAlive() const
{
    return m_bodies->pigsAlive();
}

bool GameWorld::hasNonFiniteState() const
{
    return m_bodies->hasNonFiniteState();
}

const std::vector<Entity>& GameWorld::entities() const
{
    return m_bodies->entities();
}

std::vector<DestroyedEvent> GameWorld::takeDestroyedEvents()
{
    return m_bodies->takeDestroyedEvents();
}

std::vector<BlastEvent> GameWorld::takeBlastEvents()
{
    return m_damage->takeBlastEvents();
}

const LevelDef& GameWorld::level() const
{
    return m_bodies->level();
}

double GameWorld::surfaceBelow(double x, double fromY) const
{
    return m_bodies->surfaceBelow(x, fromY);
}

const Catalog& GameWorld::catalog() const
{
    return m_bodies->catalog();
}

b2World& GameWorld::box2d()
{
    return m_bodies->world();
}

const b2World& GameWorld::box2d() const
{
    return m_bodies->world();
}

} // namespace abalike

#include "shell/SessionJson.hpp"

#include <abalike/world/WorldDigest.hpp>

namespace abalike::app
{

namespace
{

using Json = nlohmann::ordered_json;

Json contactJson(const std::optional<ContactPoint>& c)
{
    if (!c)
        return nullptr;
    return Json{{"t", c->t}, {"x", c->x}, {"y", c->y}};
}

Json abilityJson(const std::optional<AbilityUse>& use)
{
    if (!use)
        return nullptr;
    Json impulses = Json::array();
    for (const AbilityImpulse& j : use->impulses)
        impulses.push_back(
            {{"t", j.tS}, {"x", j.x}, {"y", j.y}, {"jx", j.impulseX}, {"jy", j.impulseY}, {"target", j.target}});
    return Json{{"name", use->ability},
                {"t", use->tS},
                {"x", use->x},
                {"y", use->y},
                {"before_contact", use->beforeContact},
                {"changed_flight", use->changedFlight},
                {"impulses", std::move(impulses)}};
}

Json energyJson(const std::optional<FlightEnergy>& energy)
{
    if (!energy)
        return nullptr;
    return Json{{"kinetic_j", energy->kineticJ},
                {"potential_j", energy->potentialJ},
                {"drag_loss_j", energy->dragLossJ},
                {"launch_kinetic_j", energy->launchKineticJ},
                {"launch_potential_j", energy->launchPotentialJ}};
}

Json impactJson(const std::optional<FirstImpact>& impact)
{
    if (!impact)
        return nullptr;
    const auto linear = [](const BodyVelocity& v)
    {
        return Json{v.vx, v.vy};
    };
    const auto full = [](const BodyVelocity& v)
    {
        return Json{v.vx, v.vy, v.omegaRadPerS};
    };
    const auto pair = [](const Vec2& p)
    {
        return Json{p.x, p.y};
    };
    Json out;
    out["t"] = impact->tS;
    out["body"] = {{"kind", entityKindName(impact->bodyKind)}, {"index", impact->bodyIndex}};
    out["bird_before"] = linear(impact->birdBefore);
    out["bird_after"] = linear(impact->birdAfter);
    out["body_before"] = full(impact->bodyBefore);
    out["body_after"] = full(impact->bodyAfter);
    out["body_mass_kg"] = impact->bodyMassKg;
    out["momentum_before"] = pair(impact->momentumBefore());
    out["momentum_after"] = pair(impact->momentumAfter());
    out["kinetic_before_j"] = impact->kineticBeforeJ();
    out["kinetic_after_j"] = impact->kineticAfterJ();
    out["damage_ns"] = impact->damageNs;
    out["strength_before_ns"] = impact->strengthBeforeNs;
    out["broke"] = impact->broke;
    // The momentum balance of that step, each as [x, y] in kg m/s: bird_change + body_change equals the sum of the
    // impulses from outside the pair, up to balance_residual (Box2D's float rounding).
    out["bird_change"] = pair(impact->birdChange());
    out["body_change"] = pair(impact->bodyChange());
    out["push_on_body"] = pair(impact->balance.pushOnBody);
    out["from_supports"] = pair(impact->balance.supports);
    out["bird_other_contacts"] = pair(impact->balance.birdOtherContacts);
    out["gravity"] = pair(impact->balance.gravity);
    out["break_through"] = pair(impact->balance.breakThrough);
    out["balance_residual"] = pair(impact->balanceResidual());
    // Told as physics (docs/cli.md): the impulse bird and body exchanged (on the body; the bird got the opposite),
    // every other body the bird pushed in that step with its own impulse, and where a broken block's momentum went.
    out["exchanged"] = pair(impact->exchanged());
    Json partners = Json::array();
    for (const ImpactPartner& partner : impact->partners)
        partners.push_back({{"kind", entityKindName(partner.kind)},
                            {"index", partner.index},
                            {"type", partner.type},
                            {"impulse", pair(partner.impulse)}});
    out["partners"] = std::move(partners);
    out["handed_on"] = pair(impact->handedOn);
    return out;
}

Json pathJson(const std::vector<TrackPoint>& path)
{
    Json out = Json::array();
    for (const auto& p : path)
        out.push_back({p.timeS, p.position.x, p.position.y});
    return out;
}

} // namespace

nlohmann::ordered_json defeatJson(const DestroyedEvent& defeat)
{
    Json out;
    out["t"] = defeat.timeS;
    out["shot"] = defeat.shot >= 0 ? Json(defeat.shot) : Json(nullptr);
    out["kind"] = defeat.kind == EntityKind::Pig ? "pig" : "block";
    out["index"] = defeat.index;
    Json cause;
    cause["kind"] = causeName(defeat.cause);
    cause["index"] = defeat.cause.index >= 0 ? Json(defeat.cause.index) : Json(nullptr);
    out["cause"] = std::move(cause);
    return out;
}

nlohmann::ordered_json sessionToJson(const GameSession& session)
{
    const ScoreBreakdown score = session.score();
    Json out;
    out["level"] = session.level().id;
    out["won"] = session.phase() == Phase::Won;
    out["score"] = score.total();
    out["stars"] = session.stars();
    out["pigs_remaining"] = session.pigsRemaining();
    out["birds_used"] = session.birdsUsed();
    out["sim_time_s"] = session.simTime();
    out["bodies_digest"] = bodiesDigest(session.world());
    out["score_breakdown"] = {{"block_points", score.blockPoints},
                              {"blocks_destroyed", score.blocksDestroyed},
                              {"pig_points", score.pigPoints},
                              {"pigs_defeated", score.pigsDefeated},
                              {"unused_bird_bonus", score.unusedBirdBonus},
                              {"accuracy_bonus", score.accuracyBonus}};
    out["score_breakdown"]["unused_birds"] = score.unusedBirds;
    out["score_breakdown"]["efficiency_bonus"] = score.efficiencyBonus;
    out["score_breakdown"]["accurate_shots"] = score.accurateShots;
    Json shots = Json::array();
    for (const ShotRecord& shot : session.shots())
    {
        Json s;
        s["bird"] = shot.bird;
        s["angle_deg"] = shot.angleDeg;
        s["speed"] = shot.speedMps;
        s["slingshot"] = {{"pull_m", shot.pull.pullM},
                          {"force_n", shot.pull.forceN},
                          {"energy_j", shot.pull.energyJ},
                          {"bird_energy_j", shot.pull.birdEnergyJ},
                          {"band_energy_j", shot.pull.bandEnergyJ}};
        s["predicted_contact"] = contactJson(shot.predictedContact);
        s["actual_contact"] = contactJson(shot.actualContact);
        s["deviation_m"] = shot.deviationM ? Json(*shot.deviationM) : Json(nullptr);
        s["launched_into_moving_world"] = shot.launchedIntoMovingWorld;
        s["predicted_path"] = pathJson(shot.predictedPath);
        s["actual_path"] = pathJson(shot.actualPath);
        s["first_touched"] = shot.firstTouched ? Json(entityKindName(*shot.firstTouched)) : Json(nullptr);
        s["pigs_defeated"] = shot.pigsDefeated;
        s["accuracy_points"] = shot.accuracyPoints;
        s["ability"] = abilityJson(shot.ability);
        s["energy"] = energyJson(shot.energy);
        s["impact"] = impactJson(shot.impact);
        s["ready_after_contact_s"] = shot.readyAfterContactS ? Json(*shot.readyAfterContactS) : Json(nullptr);
        shots.push_back(std::move(s));
    }
    out["shots"] = std::move(shots);
    Json defeats = Json::array();
    for (const DestroyedEvent& defeat : session.defeats())
        defeats.push_back(defeatJson(defeat));
    out["defeats"] = std::move(defeats);
    return out;
}

} // namespace abalike::app

#include <abalike/teach/ImpactAccount.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/Entity.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace abalike
{

namespace
{

double impulseSize(const Vec2& v)
{
    return std::hypot(v.x, v.y);
}

std::string impactText(const char* pattern, auto... values)
{
    char text[320];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

/// How a sentence names a body: "the small pig", "a TNT crate", "an ice block", "the ground".
std::string impactBodyName(EntityKind kind, const std::string& type, const Catalog& catalog)
{
    if (kind == EntityKind::Ground)
        return "the ground";
    if (kind == EntityKind::Terrain)
        return "the hill";
    if (kind == EntityKind::Pig)
        return "the " + type + " pig";
    if (kind == EntityKind::Bird)
        return "another bird";
    if (const Material* material = catalog.findMaterial(type);
        material != nullptr && material->look.surface == SurfaceKind::Crate)
        return "a " + material->look.label + " crate";
    const bool vowel = !type.empty() && std::string("aeiou").find(type[0]) != std::string::npos;
    return (vowel ? "an " : "a ") + type + " block";
}

/// "the" for a body named with "a"/"an", so a second mention reads right: "the wood block".
std::string namedAgain(const std::string& name)
{
    if (name.starts_with("a "))
        return "the " + name.substr(2);
    if (name.starts_with("an "))
        return "the " + name.substr(3);
    return name;
}

} // namespace

ImpactAccount accountImpact(const FirstImpact& impact, const Catalog& catalog)
{
    ImpactAccount account;
    account.bodyName = impactBodyName(impact.bodyKind, impact.bodyType, catalog);
    account.bodyIsPig = impact.bodyKind == EntityKind::Pig;
    account.exchanged = impact.exchanged();
    account.birdChange = impact.birdChange();
    for (const ImpactPartner& partner : impact.partners)
    {
        if (impulseSize(partner.impulse) > ImpactAccount::kNamedImpulseNs)
            account.partners.push_back({impactBodyName(partner.kind, partner.type, catalog), partner.impulse});
        else
            account.unnamed = account.unnamed + partner.impulse;
    }
    std::stable_sort(account.partners.begin(), account.partners.end(),
                     [](const auto& a, const auto& b) { return impulseSize(a.impulse) > impulseSize(b.impulse); });
    account.carriedBefore = impact.birdMassKg * std::hypot(impact.birdBefore.vx, impact.birdBefore.vy);
    account.carriedAfter = impact.birdMassKg * std::hypot(impact.birdAfter.vx, impact.birdAfter.vy);
    account.birdKeptDirection = impact.birdAfter.vx * impact.birdBefore.vx > 0.0;
    account.damageNs = impact.damageNs;
    account.strengthNs = impact.strengthBeforeNs;
    account.broke = impact.broke;
    if (impact.broke && !account.bodyIsPig)
    {
        const Vec2 momentum{impact.bodyMassKg * impact.bodyAfter.vx, impact.bodyMassKg * impact.bodyAfter.vy};
        account.handedOn = impact.handedOn;
        account.withSplinters = momentum - impact.handedOn;
    }
    if (!impact.broke)
        account.bounciness = impact.restitution();
    return account;
}

std::string damageOfStrength(double damageNs, double strengthNs)
{
    int decimals = 0;
    // Enough decimals that two different values do not print alike (59.96 of 60 is "59.96 of the 60").
    while (decimals < 2 && damageNs < strengthNs &&
           impactText("%.*f", decimals, damageNs) == impactText("%.*f", decimals, strengthNs))
        ++decimals;
    return impactText("%.*f of the %.0f N\u00B7s", decimals, damageNs, strengthNs);
}

std::string impactSentence(const ImpactAccount& a)
{
    std::string text =
        impactText("The bird hit %s carrying %.0f kg\u00B7m/s of momentum. ", a.bodyName.c_str(), a.carriedBefore);
    const std::string body = namedAgain(a.bodyName);
    // Newton's third law: one impulse, given by the bird and returned in full by the body.
    text += impactText("They pushed each other with %.0f N\u00B7s, equal and opposite", impulseSize(a.exchanged));
    if (a.broke)
        text += impactText(", before %s %s", body.c_str(), a.bodyIsPig ? "was defeated" : "broke");
    for (std::size_t i = 0; i < a.partners.size(); ++i)
        text += impactText("%s %s with %.0f N\u00B7s", i == 0 ? "; the bird also pushed" : ",",
                           a.partners[i].name.c_str(), impulseSize(a.partners[i].impulse));
    const double change = impulseSize(a.birdChange);
    text += impactText(". So the bird's momentum changed by %.0f N\u00B7s, from %.0f to %.0f kg\u00B7m/s", change,
                       a.carriedBefore, a.carriedAfter);
    if (std::abs(change - std::abs(a.carriedBefore - a.carriedAfter)) >= 1.0)
        text += " (momentum has a direction: the change is a vector)";
    if (!a.birdKeptDirection)
        text += impulseSize(a.exchanged) > a.carriedBefore * 1.02 && !a.broke
                    ? "; it bounced back, which takes more than it carried"
                    : "; it was turned back";
    text += ". ";
    std::string subject = body;
    subject[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(subject[0])));
    if (a.broke)
    {
        // Only here does "all" appear: the damage reached what the body could still take.
        text +=
            impactText("%s took all the %.0f N\u00B7s of damage it could still take", subject.c_str(), a.strengthNs);
        const double handed = impulseSize(a.handedOn);
        const double left = impulseSize(a.withSplinters);
        if (handed >= 0.5 && left >= 0.5)
            text += impactText("; its momentum went on to what it pushed (%.0f N\u00B7s) and with its splinters "
                               "(%.0f kg\u00B7m/s)",
                               handed, left);
        else if (handed >= 0.5)
            text += impactText("; its momentum, %.0f N\u00B7s, went on to what it pushed", handed);
        else if (left >= 0.5)
            text += impactText("; its momentum, %.0f kg\u00B7m/s, left with its splinters", left);
        text += ".";
    }
    else if (a.damageNs > 0.0)
        text += impactText("%s held: it took %s of damage it could take (every push on it counts, the bird's and that "
                           "of what it rests on).",
                           subject.c_str(), damageOfStrength(a.damageNs, a.strengthNs).c_str());
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

} // namespace abalike

#include <abalike/teach/SchoolWording.hpp>
#include <array>
#include <cctype>

namespace abalike
{

namespace
{

constexpr std::array<std::string_view, 21> kTerms = {
    "RK4",      "Runge",   "Kutta",   "Box2D",      "odeint",        "TOI",           "time of impact",
    "sub-step", "substep", "chord",   "integrator", "semi-implicit", "restitution",   "rad/s",
    "dopri5",   "sagitta", "b2World", "evaluation", "step size",     "smaller steps", "scientific notation",
};

/// "2.1e-07", "4.5e-13": a number in scientific notation, which a school course does not read yet.
bool scientificNumberAt(std::string_view text, std::size_t at)
{
    if (at == 0 || !std::isdigit(static_cast<unsigned char>(text[at - 1])) || (text[at] != 'e' && text[at] != 'E'))
        return false;
    std::size_t next = at + 1;
    if (next < text.size() && (text[next] == '-' || text[next] == '+'))
        ++next;
    return next < text.size() && std::isdigit(static_cast<unsigned char>(text[next]));
}

bool isWordCharacter(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

/// Acronyms and units (anything with a digit, a capital after the first letter or a slash) match exactly; words in
/// any case, and with an ending ("sub-steps", "chords").
bool exact(std::string_view term)
{
    for (std::size_t i = 0; i < term.size(); ++i)
        if (std::isdigit(static_cast<unsigned char>(term[i])) || term[i] == '/' ||
            (i > 0 && std::isupper(static_cast<unsigned char>(term[i]))))
            return true;
    return false;
}

bool sameLetters(std::string_view a, std::string_view b, bool caseMatters)
{
    for (std::size_t i = 0; i < a.size(); ++i)
        if (caseMatters
                ? a[i] != b[i]
                : std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

} // namespace

std::span<const std::string_view> universityOnlyTerms()
{
    return kTerms;
}

std::optional<std::string_view> universityTermIn(std::string_view text)
{
    for (std::size_t at = 0; at < text.size(); ++at)
        if (scientificNumberAt(text, at))
            return kTerms.back();
    for (const std::string_view term : kTerms)
    {
        const bool caseMatters = exact(term);
        for (std::size_t at = 0; at + term.size() <= text.size(); ++at)
        {
            if (!sameLetters(term, text.substr(at, term.size()), caseMatters))
                continue;
            const bool startsWord = at == 0 || !isWordCharacter(text[at - 1]);
            const std::size_t end = at + term.size();
            // Words may take an ending ("sub-steps"); acronyms and units end where they end ("TOIs" is no term).
            const bool endsWord =
                end == text.size() || !isWordCharacter(text[end]) || (!caseMatters && text[end] == 's');
            if (startsWord && endsWord)
                return term;
        }
    }
    return std::nullopt;
}

} // namespace abalike

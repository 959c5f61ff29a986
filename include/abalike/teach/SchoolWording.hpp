#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace abalike
{

/// School wording is for ages 14-16: it names what happens, not the machinery that computes it. These are the
/// terms only university wording may show (the integrator, the physics engine and its steps, units and quantities
/// a school course does not use yet). One list, for the game's texts and the tests that walk them.
std::span<const std::string_view> universityOnlyTerms();

/// The first university-only term in text (whole words; acronyms and units exactly, words in any case), or nullopt.
std::optional<std::string_view> universityTermIn(std::string_view text);

} // namespace abalike

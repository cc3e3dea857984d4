#pragma once
// "Did you mean" for a misspelt name, shared by the checker's diagnostics and the command-line
// flags and viewer commands that take a name from the file.
#include <span>
#include <string>
#include <string_view>

namespace voxc {

// "; did you mean 'size'?" for the candidate closest to `name` when it is close enough
// (a few edits, or a difference in case only); an empty string otherwise, and for names of
// more than 64 characters.
std::string didYouMean(std::string_view name, std::span<const std::string_view> candidates);

// The candidate didYouMean would suggest, or an empty view.
std::string_view closestName(std::string_view name, std::span<const std::string_view> candidates);

// didYouMean, or " (expected one of: a, b, c)" when no candidate is close.
std::string suggestOrList(std::string_view name, std::span<const std::string_view> candidates);

} // namespace voxc

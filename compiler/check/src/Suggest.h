#pragma once
#include <span>
#include <string>
#include <string_view>

namespace voxc::check {

// "; did you mean 'size'?" for the candidate closest to `name` when it is close enough
// (a few edits, or a difference in case only); an empty string otherwise.
std::string didYouMean(std::string_view name, std::span<const std::string_view> candidates);

// didYouMean, or " (expected one of: a, b, c)" when no candidate is close.
std::string suggestOrList(std::string_view name, std::span<const std::string_view> candidates);

} // namespace voxc::check

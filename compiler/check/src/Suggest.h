#pragma once
#include "voxc/syntax/Diagnostics.h"

#include <span>
#include <string>
#include <string_view>

namespace voxc::check {

// "; did you mean 'size'?" for the candidate closest to `name` when it is close enough
// (a few edits, or a difference in case only); an empty string otherwise, and for names of
// more than 64 characters.
std::string didYouMean(std::string_view name, std::span<const std::string_view> candidates);

// didYouMean, or " (expected one of: a, b, c)" when no candidate is close.
std::string suggestOrList(std::string_view name, std::span<const std::string_view> candidates);

// False once `diagnostics` drops further errors: the callers that gather every name the file
// declares for a suggestion skip that work then, which would otherwise cost names x errors.
inline bool errorsStillShown(const Diagnostics& diagnostics) {
    return diagnostics.errorCount() < Diagnostics::kMaxErrors;
}

} // namespace voxc::check

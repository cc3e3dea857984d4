#pragma once
#include "voxc/core/Suggest.h"
#include "voxc/syntax/Diagnostics.h"

namespace voxc::check {

// False once `diagnostics` drops further errors: the callers that gather every name the file
// declares for a suggestion skip that work then, which would otherwise cost names x errors.
inline bool errorsStillShown(const Diagnostics& diagnostics) {
    return diagnostics.errorCount() < Diagnostics::kMaxErrors;
}

} // namespace voxc::check

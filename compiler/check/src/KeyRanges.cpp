#include "voxc/check/KeyRanges.h"

#include <cstdint>
#include <limits>

namespace voxc {

std::optional<KeyRange> grammarKeyRange(std::string_view block, std::string_view key, const Limits& limits) {
    if (block == "grammar" && key == "iterations") return KeyRange{1.0, double(limits.maxIterations), true};
    if (block != "rule") return std::nullopt;
    if (key == "probability") return KeyRange{0.0, 1.0, false};
    if (key == "priority")
        return KeyRange{double(std::numeric_limits<int32_t>::min()), double(std::numeric_limits<int32_t>::max()), true};
    // One thousandth is the weight's unit; anything that rounds to 0 units is refused.
    if (key == "weight") return KeyRange{0.5 / kWeightUnitsPerOne, 1000.0, false};
    return std::nullopt;
}

} // namespace voxc

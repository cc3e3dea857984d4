#pragma once
#include <cstdint>

namespace voxc {

// 1-based line and column of the first character; length in characters (at least 1).
struct SourceLoc {
    uint32_t line = 0;
    uint32_t column = 0;
    uint32_t length = 1;
};

} // namespace voxc

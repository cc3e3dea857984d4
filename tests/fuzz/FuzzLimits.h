#pragma once
// The limits the check and lower fuzz targets check with.
#include "voxc/program/Program.h"

namespace voxc::fuzz {

// The checker's limits with the host solves (curves, terrain) capped low, so an input that asks
// for a large solve is an E0012 in microseconds instead of seconds of legitimate work, which the
// fuzzer's per-input timeout would report as a hang.
inline Limits fuzzLimits() {
    Limits limits;
    limits.maxSolveCells = 4096;
    limits.maxTerrainWork = 1'000'000;
    return limits;
}

} // namespace voxc::fuzz

#pragma once
// What every fuzz target does with libFuzzer's bytes: take them as the text of a .vox file.
#include "voxc/program/Program.h"
#include "voxc/syntax/SourceFile.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace voxc::fuzz {

inline SourceFile sourceFromBytes(const uint8_t* data, size_t size) {
    return SourceFile("fuzz.vox", std::string(reinterpret_cast<const char*>(data), size));
}

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

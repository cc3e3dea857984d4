#pragma once
// What every fuzz target does with libFuzzer's bytes: take them as the text of a .vox file.
#include "voxc/syntax/SourceFile.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace voxc::fuzz {

inline SourceFile sourceFromBytes(const uint8_t* data, size_t size) {
    return SourceFile("fuzz.vox", std::string(reinterpret_cast<const char*>(data), size));
}

} // namespace voxc::fuzz

#pragma once
// The ranges the language gives the numeric keys of grammar and rule blocks (docs/language.md),
// in one place for the checker that enforces them and the viewer's sliders that offer them.
#include "voxc/program/Program.h"

#include <optional>
#include <string_view>

namespace voxc {

struct KeyRange {
    double min = 0.0; // inclusive
    double max = 0.0; // inclusive
    bool integer = false;
};

// `block` is "grammar" (iterations: 1 .. limits.maxIterations) or "rule" (probability: 0 .. 1,
// priority: any int32, weight: 0.0005 .. 1000); nothing for any other key.
std::optional<KeyRange> grammarKeyRange(std::string_view block, std::string_view key, const Limits& limits = {});

} // namespace voxc

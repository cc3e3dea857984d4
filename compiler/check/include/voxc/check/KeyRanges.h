#pragma once
// The ranges the language gives numeric keys (docs/language.md), in one place for the checker that
// enforces them and the viewer's sliders that offer them.
#include "voxc/program/Program.h"

#include <optional>
#include <span>
#include <string_view>

namespace voxc {

struct KeyRange {
    double min = 0.0; // inclusive
    double max = 0.0; // inclusive
    bool integer = false;
    // The value the language takes when the file leaves the key out, where that is one number
    // (not, say, the world's size or an enclosing block's key).
    std::optional<double> absent = {};
};

// `block` is "grammar" (iterations: 1 .. limits.maxIterations) or "rule" (probability: 0 .. 1,
// priority: any int32, weight: 0.0005 .. 1000); nothing for any other key.
std::optional<KeyRange> grammarKeyRange(std::string_view block, std::string_view key, const Limits& limits = {});

// A number or integer key of a curves, terrain or lsystem block or of a block nested in one, by the
// kind of the block that holds it: "curves", "constraint" (a curve's constraint point); "terrain",
// "noise", "spline", "meta" (a spline's meta point); "lsystem".
struct BlockKey {
    std::string_view block, key;
    KeyRange range;
};

// Every such key of blocks of kind `block`, in the order docs/language.md lists them; empty for
// any other kind.
std::span<const BlockKey> blockKeys(std::string_view block);
// The range of one of them; nothing for any other key.
std::optional<KeyRange> blockKeyRange(std::string_view block, std::string_view key);

} // namespace voxc

#pragma once
// The two typed errors the generators with a numeric domain (terrain, curves) throw from their
// checks. Both are UserErrors: the numbers come from the user's file, and the checker locates them.
// Each generator derives its own pair, which names it in the message.
#include "voxc/core/Errors.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace voxc::generators {

// A size or an amount of work over its limit: `quantity` names it, `value` and `limit` are the numbers.
struct LimitError : UserError {
    LimitError(std::string_view generator, std::string quantity, uint64_t value, uint64_t limit);
    std::string quantity;
    uint64_t value;
    uint64_t limit;
};

// A value outside its valid range or an unusable combination: `parameter` names it as the user
// writes it, `value` is its value, `requirement` the rule broken.
struct ParameterError : UserError {
    ParameterError(std::string_view generator, std::string parameter, double value, std::string requirement);
    std::string parameter;
    double value;
    std::string requirement;
};

} // namespace voxc::generators

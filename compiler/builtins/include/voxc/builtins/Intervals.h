#pragma once
// Conservative interval rules for builtin functions: for argument values anywhere inside the
// argument intervals, the interpreter's result (FunctionInfo::eval, float rounding included)
// lies inside the rule's result. Kept beside the registry rather than in FunctionInfo so the
// records stay unchanged; a function without a rule is unknown (every component (-inf, +inf)).
// The result also holds the GPU's value within the record's tolerance. A rule answers unknown
// wherever the float result could be NaN (a NaN lies in no interval). Rules that only pick or
// clamp inputs (min, max, clamp, abs, floor, select, density's saturation) are exact, so a
// degenerate result proves an exact float; arithmetic widens.
#include "voxc/program/Field.h"

#include <glm/vec3.hpp>
#include <span>
#include <string_view>

namespace voxc {

// Per-component bounds of a field value as doubles. Bool: 0 (false) / 1 (true); Int: integer
// bounds; Float uses x. A bound may be infinite; lo > hi never happens.
struct Interval {
    Type type = Type::Float;
    glm::dvec3 lo{0.0}, hi{0.0};
    // The value is exactly the float(s) lo (== hi), signed zero included. Only constants and
    // rules that pass an exact operand through set it: a degenerate arithmetic result is not exact.
    bool exact = false;

    static Interval point(Type type, glm::dvec3 v) { return {type, v, v, true}; }
    static Interval unknown(Type type);
};

using RangeRule = Interval (*)(std::span<const Interval> args);

// The rule of a builtin (by FunctionInfo::name), or nullptr when it has none.
RangeRule rangeRule(std::string_view function);

} // namespace voxc

#pragma once
// The builtin-function records, grouped by file; voxc::functions() concatenates the groups.
#include "voxc/builtins/Functions.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <span>

namespace voxc::function_records {

std::span<const FunctionInfo> mathFunctions();  // Math.cpp
std::span<const FunctionInfo> noiseFunctions(); // NoiseRecords.cpp
std::span<const FunctionInfo> operatorFunctions(); // Operators.cpp
std::span<const FunctionInfo> sdfFunctions();      // Sdf.cpp

inline int componentCount(Type t) { return t == Type::Vec3 ? 3 : t == Type::Vec2 ? 2 : 1; }
inline bool isFloatLike(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3; }
inline bool isVector(Type t) { return t == Type::Vec2 || t == Type::Vec3; }

// IEEE minNum / maxNum, math_functions.glsl's mathMin / mathMax: b < a ? b : a (a < b ? b : a),
// ties keeping a, unless a is NaN: then b (a NaN b already loses the comparison). So a NaN
// operand is ignored and only two NaNs give NaN. GLSL's own min / max leave NaN undefined.
inline float minOf(float a, float b) { return std::isnan(a) ? b : (b < a ? b : a); }
inline float maxOf(float a, float b) { return std::isnan(a) ? b : (a < b ? b : a); }

// "f(a, b, ...)" from a function name and GLSL argument expressions.
std::string call(std::string_view function, std::span<const std::string> args);

// A type rule's test: the argument types are exactly these.
inline bool matches(std::span<const Type> args, std::initializer_list<Type> expected) {
    return std::equal(args.begin(), args.end(), expected.begin(), expected.end());
}
// A record's GLSL: a call of the function Name with the arguments as they are.
template <const char* Name>
std::string glslCall(std::span<const std::string> args, std::span<const Type>) { return call(Name, args); }

constexpr std::span<const std::string_view> kNone{}; // a record that needs no GLSL library
constexpr float kExact = 0.0f;                        // a record whose GLSL equals the interpreter bit for bit
constexpr std::string_view kMathLibrary[] = {"math_functions.glsl"}; // mathMin, mathMax, ...

} // namespace voxc::function_records

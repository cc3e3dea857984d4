#pragma once
// The builtin-function records, grouped by file; voxc::functions() concatenates the groups.
#include "voxc/builtins/Functions.h"

#include <span>

namespace voxc::function_records {

std::span<const FunctionInfo> mathFunctions();  // Math.cpp
std::span<const FunctionInfo> noiseFunctions(); // NoiseRecords.cpp
std::span<const FunctionInfo> operatorFunctions(); // Operators.cpp
std::span<const FunctionInfo> sdfFunctions();      // Sdf.cpp

inline bool isFloatLike(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3; }
inline bool isVector(Type t) { return t == Type::Vec2 || t == Type::Vec3; }

// "f(a, b, ...)" from a function name and GLSL argument expressions.
std::string call(std::string_view function, std::span<const std::string> args);

} // namespace voxc::function_records

// Math builtins. Each evaluates exactly as GLSL defines it (mix, smoothstep, fract, clamp as
// min(max())) in the same operation order as compiler/shaders/math_functions.glsl, so the
// correctly rounded ones agree bit for bit. min and max are IEEE minNum / maxNum (a NaN
// operand is ignored), written out on both sides because GLSL leaves NaN operands undefined.
#include "Records.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxc::function_records {

namespace {

float component(const Value& value, int c) { return value.type == Type::Float ? value.v.x : value.v[c]; }

// Applies `f` per component; a float argument is broadcast; the result has the widest argument type.
template <size_t N, typename F>
Value componentwise(std::span<const Value> args, F f) {
    Type result = Type::Float;
    for (const Value& a : args)
        if (componentCount(a.type) > componentCount(result)) result = a.type;
    Value out;
    out.type = result;
    for (int c = 0; c < componentCount(result); ++c) {
        float x[N];
        for (size_t i = 0; i < N; ++i) x[i] = component(args[i], c);
        out.v[c] = f(x);
    }
    return out;
}

// Type rules. A "T" is float, vec2 or vec3.
std::optional<Type> sameT(std::span<const Type> a, size_t n) { // f(T, ..., T) -> T
    if (a.size() != n || !isFloatLike(a[0])) return std::nullopt;
    for (Type t : a)
        if (t != a[0]) return std::nullopt;
    return a[0];
}
std::optional<Type> unaryT(std::span<const Type> a) { return sameT(a, 1); }
std::optional<Type> binaryT(std::span<const Type> a) { return sameT(a, 2); }
// min/max(T, T) or (vec, float) -> T
std::optional<Type> minMaxRule(std::span<const Type> a) {
    if (a.size() == 2 && isVector(a[0]) && a[1] == Type::Float) return a[0];
    return sameT(a, 2);
}
// clamp(T, T, T) or (vec, float, float) -> T
std::optional<Type> clampRule(std::span<const Type> a) {
    if (a.size() == 3 && isVector(a[0]) && a[1] == Type::Float && a[2] == Type::Float) return a[0];
    return sameT(a, 3);
}
// mix(T, T, T) or (vec, vec, float) -> T
std::optional<Type> mixRule(std::span<const Type> a) {
    if (a.size() == 3 && isVector(a[0]) && a[1] == a[0] && a[2] == Type::Float) return a[0];
    return sameT(a, 3);
}
// smoothstep(T, T, T) or (float, float, vec) -> T
std::optional<Type> smoothstepRule(std::span<const Type> a) {
    if (a.size() == 3 && a[0] == Type::Float && a[1] == Type::Float && isVector(a[2])) return a[2];
    return sameT(a, 3);
}
std::optional<Type> vectorToFloat(std::span<const Type> a) { // length(vec) -> float
    if (a.size() == 1 && isVector(a[0])) return Type::Float;
    return std::nullopt;
}
std::optional<Type> dotRule(std::span<const Type> a) {
    if (a.size() == 2 && isVector(a[0]) && a[1] == a[0]) return Type::Float;
    return std::nullopt;
}
std::optional<Type> vec2Rule(std::span<const Type> a) {
    if (a.size() == 2 && a[0] == Type::Float && a[1] == Type::Float) return Type::Vec2;
    return std::nullopt;
}
std::optional<Type> vec3Rule(std::span<const Type> a) {
    if (a.size() == 3 && a[0] == Type::Float && a[1] == Type::Float && a[2] == Type::Float) return Type::Vec3;
    return std::nullopt;
}

// pow is NaN where GLSL leaves it undefined (x < 0, or x = 0 with y <= 0) and where the device's
// exp2(y * log2(x)) is NaN though the C library's pow is not (a NaN operand, x = 1 with y
// infinite, x infinite with y = 0); elsewhere both compute x^y within the record's tolerance.
// math_functions.glsl's mathPow tests the same cases.
float powOf(float x, float y) {
    const bool undefined = std::isnan(x) || std::isnan(y) || x < 0.0f || (x == 0.0f && y <= 0.0f) ||
                           (x == 1.0f && std::isinf(y)) || (std::isinf(x) && y == 0.0f);
    return undefined ? std::numeric_limits<float>::quiet_NaN() : std::pow(x, y);
}

float mixOf(float x, float y, float a) { return x * (1.0f - a) + y * a; }
float smoothstepOf(float e0, float e1, float x) {
    const float t = minOf(maxOf((x - e0) / (e1 - e0), 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
float dotOf(const Value& a, const Value& b) {
    float r = a.v.x * b.v.x + a.v.y * b.v.y;
    if (a.type == Type::Vec3) r = r + a.v.z * b.v.z;
    return r;
}

// GLSL emitters: a GLSL function applied to the arguments, or a fixed expression.

constexpr char kMin[] = "mathMin", kMax[] = "mathMax", kAbs[] = "abs", kFloor[] = "floor", kSqrt[] = "sqrt",
               kPow[] = "mathPow", kSin[] = "sin", kCos[] = "cos", kMix[] = "mathMix", kSmoothstep[] = "mathSmoothstep",
               kFract[] = "mathFract", kLength[] = "mathLength", kDot[] = "mathDot", kVec2[] = "vec2",
               kVec3[] = "vec3";

std::string clampGlsl(std::span<const std::string> a, std::span<const Type>) {
    return "mathMin(mathMax(" + a[0] + ", " + a[1] + "), " + a[2] + ")";
}


// Tolerances (Vulkan precision rules, on the domains tests/functions samples; see docs/functions.md).
constexpr float kSqrtTolerance = 4e-5f;    // 3 ulp-ish relative, results up to 100 (args up to 1e4)
constexpr float kLengthTolerance = 1e-4f;  // as sqrt, results up to 173 (components up to 100)
constexpr float kPowTolerance = 2e-3f;     // exp2(y log2 x), 3 + 2|y log2 x| ulp: results up to 1000 on x in [0.1, 10], |y| <= 3
constexpr float kTrigTolerance = 4.8828125e-4f; // 2^-11 absolute on [-pi, pi]
constexpr float kDivisionTolerance = 1e-6f;     // one division (2.5 ulp) feeding a cubic on [0, 1]

const FunctionInfo kMath[] = {
    {"min", "min(a: T, b: T) -> T; b may be float; T = float, vec2, vec3",
     "component-wise minimum (b < a ? b : a); a NaN operand is ignored", minMaxRule,
     [](std::span<const Value> a) { return componentwise<2>(a, [](const float* x) { return minOf(x[0], x[1]); }); },
     glslCall<kMin>, kMathLibrary, kExact},
    {"max", "max(a: T, b: T) -> T; b may be float; T = float, vec2, vec3",
     "component-wise maximum (a < b ? b : a); a NaN operand is ignored", minMaxRule,
     [](std::span<const Value> a) { return componentwise<2>(a, [](const float* x) { return maxOf(x[0], x[1]); }); },
     glslCall<kMax>, kMathLibrary, kExact},
    {"clamp", "clamp(x: T, lo: T, hi: T) -> T; lo, hi may be float; T = float, vec2, vec3",
     "min(max(x, lo), hi) component-wise (hi wins when lo > hi; clamp(NaN, lo, hi) = lo)", clampRule,
     [](std::span<const Value> a) {
         return componentwise<3>(a, [](const float* x) { return minOf(maxOf(x[0], x[1]), x[2]); });
     },
     clampGlsl, kMathLibrary, kExact},
    {"abs", "abs(x: T) -> T; T = float, vec2, vec3", "component-wise |x|", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return std::fabs(x[0]); }); },
     glslCall<kAbs>, kNone, kExact},
    {"floor", "floor(x: T) -> T; T = float, vec2, vec3", "component-wise largest integer <= x", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return std::floor(x[0]); }); },
     glslCall<kFloor>, kNone, kExact},
    {"fract", "fract(x: T) -> T; T = float, vec2, vec3", "component-wise x - floor(x), in [0, 1]", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return x[0] - std::floor(x[0]); }); },
     glslCall<kFract>, kMathLibrary, kExact},
    {"mix", "mix(x: T, y: T, a: T) -> T; a may be float; T = float, vec2, vec3", "x * (1 - a) + y * a component-wise",
     mixRule, [](std::span<const Value> a) { return componentwise<3>(a, [](const float* x) { return mixOf(x[0], x[1], x[2]); }); },
     glslCall<kMix>, kMathLibrary, kExact},
    {"smoothstep", "smoothstep(e0: T, e1: T, x: T) -> T; e0, e1 may be float; T = float, vec2, vec3",
     "t * t * (3 - 2t), t = clamp((x - e0) / (e1 - e0), 0, 1); in [0, 1]", smoothstepRule,
     [](std::span<const Value> a) {
         return componentwise<3>(a, [](const float* x) { return smoothstepOf(x[0], x[1], x[2]); });
     },
     glslCall<kSmoothstep>, kMathLibrary, kDivisionTolerance},
    {"sqrt", "sqrt(x: T) -> T; T = float, vec2, vec3", "component-wise square root (x >= 0)", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return std::sqrt(x[0]); }); },
     glslCall<kSqrt>, kNone, kSqrtTolerance},
    {"pow", "pow(x: T, y: T) -> T; T = float, vec2, vec3",
     "component-wise x^y; NaN where x < 0, x = 0 with y <= 0, x = 1 with y infinite or x infinite with y = 0",
     binaryT, [](std::span<const Value> a) { return componentwise<2>(a, [](const float* x) { return powOf(x[0], x[1]); }); },
     glslCall<kPow>, kMathLibrary, kPowTolerance},
    {"sin", "sin(x: T) -> T; T = float, vec2, vec3", "component-wise sine (radians), in [-1, 1]", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return std::sin(x[0]); }); },
     glslCall<kSin>, kNone, kTrigTolerance},
    {"cos", "cos(x: T) -> T; T = float, vec2, vec3", "component-wise cosine (radians), in [-1, 1]", unaryT,
     [](std::span<const Value> a) { return componentwise<1>(a, [](const float* x) { return std::cos(x[0]); }); },
     glslCall<kCos>, kNone, kTrigTolerance},
    {"length", "length(v: V) -> float; V = vec2, vec3", "sqrt(dot(v, v)), >= 0", vectorToFloat,
     [](std::span<const Value> a) { return Value::makeFloat(std::sqrt(dotOf(a[0], a[0]))); }, glslCall<kLength>,
     kMathLibrary, kLengthTolerance},
    {"dot", "dot(a: V, b: V) -> float; V = vec2, vec3", "a.x * b.x + a.y * b.y (+ a.z * b.z), summed left to right",
     dotRule, [](std::span<const Value> a) { return Value::makeFloat(dotOf(a[0], a[1])); }, glslCall<kDot>, kMathLibrary,
     kExact},
    {"vec2", "vec2(x: float, y: float) -> vec2", "the vector (x, y)", vec2Rule,
     [](std::span<const Value> a) { return Value::makeVec2({a[0].v.x, a[1].v.x}); }, glslCall<kVec2>, kNone, kExact},
    {"vec3", "vec3(x: float, y: float, z: float) -> vec3", "the vector (x, y, z)", vec3Rule,
     [](std::span<const Value> a) { return Value::makeVec3({a[0].v.x, a[1].v.x, a[2].v.x}); }, glslCall<kVec3>, kNone,
     kExact},
};

} // namespace

std::span<const FunctionInfo> mathFunctions() { return kMath; }

} // namespace voxc::function_records

// Signed distance builtins: primitives, CSG on distances (hard and smooth) and `density`, the
// bridge from a distance to the grammar's densities. Every record evaluates in the same
// operation order as compiler/shaders/sdf_functions.glsl (which is all `precise`), so only
// sqrt and division can make the two sides differ.
#include "Records.h"

#include <algorithm>
#include <cmath>

namespace voxc::function_records {

namespace {


template <Type... Args>
std::optional<Type> toFloat(std::span<const Type> a) { // f(Args...) -> float
    if (matches(a, {Args...})) return Type::Float;
    return std::nullopt;
}
std::optional<Type> densityRule(std::span<const Type> a) {
    if (matches(a, {Type::Float}) || matches(a, {Type::Float, Type::Float})) return Type::Float;
    return std::nullopt;
}

// min(max()) with Records.h's minOf / maxOf (a NaN operand ignored), as Math.cpp's clamp.
float clampOf(float x, float lo, float hi) { return minOf(maxOf(x, lo), hi); }

// mathDot/mathLength of math_functions.glsl: summed left to right.
float dotOf(glm::vec3 a, glm::vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float lengthOf(glm::vec3 a) { return std::sqrt(dotOf(a, a)); }

float sphere(glm::vec3 p, glm::vec3 center, float radius) { return lengthOf(p - center) - radius; }

// Exact Euclidean box distance: the length of the outside part of q plus the (negative) largest
// inside component. Negative half sizes count by their magnitude.
float box(glm::vec3 p, glm::vec3 center, glm::vec3 halfSize) {
    const glm::vec3 d = p - center;
    const glm::vec3 q(std::fabs(d.x) - std::fabs(halfSize.x), std::fabs(d.y) - std::fabs(halfSize.y),
                      std::fabs(d.z) - std::fabs(halfSize.z));
    const float outside = lengthOf({maxOf(q.x, 0.0f), maxOf(q.y, 0.0f), maxOf(q.z, 0.0f)});
    const float inside = minOf(maxOf(q.x, maxOf(q.y, q.z)), 0.0f);
    return outside + inside;
}

// Distance to the segment ab minus the radius; a == b is a sphere around a.
float capsule(glm::vec3 p, glm::vec3 a, glm::vec3 b, float radius) {
    const glm::vec3 pa = p - a, ba = b - a;
    const float baba = dotOf(ba, ba);
    const float h = baba > 0.0f ? clampOf(dotOf(pa, ba) / baba, 0.0f, 1.0f) : 0.0f;
    return lengthOf(pa - ba * h) - radius;
}

// Signed distance to dot(p, n / |n|) = offset; a zero normal gives -offset everywhere.
float plane(glm::vec3 p, glm::vec3 normal, float offset) {
    const float n = lengthOf(normal);
    return n > 0.0f ? dotOf(p, normal) / n - offset : -offset;
}

// Polynomial smooth minimum with blend radius k; k <= 0 (or NaN) is the hard minimum. Outside
// the blend band (|a - b| >= k) h is 0 or 1 and the result is exactly min(a, b).
float smoothUnion(float a, float b, float k) {
    if (!(k > 0.0f)) return minOf(a, b);
    const float h = clampOf(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
    const float blended = b * (1.0f - h) + a * h; // mathMix(b, a, h)
    return blended - k * h * (1.0f - h);
}
// Negation is exact, so the smooth maximum is the smooth minimum mirrored.
float smoothIntersect(float a, float b, float k) { return -smoothUnion(-a, -b, k); }
float smoothSubtract(float a, float b, float k) { return smoothIntersect(a, -b, k); }

// Distance to density: the surface d = 0 is exactly 0.5 (the grammar's GEQ 0.5), a ramp of
// `width` voxels; width <= 0 (or NaN) is the step it tends to.
float density(float d, float width) {
    if (!(width > 0.0f)) return d < 0.0f ? 1.0f : d > 0.0f ? 0.0f : 0.5f;
    return clampOf(0.5f - d / width, 0.0f, 1.0f);
}

float f(const Value& v) { return v.v.x; }

Value evalSphere(std::span<const Value> a) { return Value::makeFloat(sphere(a[0].v, a[1].v, f(a[2]))); }
Value evalBox(std::span<const Value> a) { return Value::makeFloat(box(a[0].v, a[1].v, a[2].v)); }
Value evalCapsule(std::span<const Value> a) { return Value::makeFloat(capsule(a[0].v, a[1].v, a[2].v, f(a[3]))); }
Value evalPlane(std::span<const Value> a) { return Value::makeFloat(plane(a[0].v, a[1].v, f(a[2]))); }
Value evalHeightfield(std::span<const Value> a) { return Value::makeFloat(a[0].v.y - f(a[1])); }
Value evalUnion(std::span<const Value> a) { return Value::makeFloat(minOf(f(a[0]), f(a[1]))); }
Value evalSubtract(std::span<const Value> a) { return Value::makeFloat(maxOf(f(a[0]), -f(a[1]))); }
Value evalIntersect(std::span<const Value> a) { return Value::makeFloat(maxOf(f(a[0]), f(a[1]))); }
template <float (*F)(float, float, float)>
Value evalSmooth(std::span<const Value> a) { return Value::makeFloat(F(f(a[0]), f(a[1]), f(a[2]))); }
Value evalDensity(std::span<const Value> a) { return Value::makeFloat(density(f(a[0]), a.size() == 2 ? f(a[1]) : 1.0f)); }

std::string unionGlsl(std::span<const std::string> a, std::span<const Type>) { return "mathMin(" + a[0] + ", " + a[1] + ")"; }
std::string subtractGlsl(std::span<const std::string> a, std::span<const Type>) {
    return "mathMax(" + a[0] + ", -(" + a[1] + "))";
}
std::string intersectGlsl(std::span<const std::string> a, std::span<const Type>) {
    return "mathMax(" + a[0] + ", " + a[1] + ")";
}
std::string densityGlsl(std::span<const std::string> a, std::span<const Type>) {
    return "sdfDensity(" + a[0] + ", " + (a.size() == 2 ? a[1] : std::string("1.0")) + ")";
}

constexpr char kSphere[] = "sdfSphere", kBox[] = "sdfBox", kCapsule[] = "sdfCapsule", kPlane[] = "sdfPlane",
               kHeightfield[] = "sdfHeightfield", kSmoothUnion[] = "sdfSmoothUnion",
               kSmoothSubtract[] = "sdfSmoothSubtract", kSmoothIntersect[] = "sdfSmoothIntersect";

constexpr std::string_view kSdfLibs[] = {"math_functions.glsl", "sdf_functions.glsl"};

// Tolerances (Vulkan precision rules, on the domain tests/functions samples: every component in
// [-50, 50]; see docs/functions.md). Sums, products, min, max and abs are exact or correctly rounded.
constexpr float kDistanceTolerance = 1e-4f;  // one sqrt (a few ulp relative) of distances up to ~350
constexpr float kCapsuleTolerance = 2e-4f;   // + one division feeding the closest point on the segment
constexpr float kPlaneTolerance = 1e-4f;     // sqrt and one division, results up to ~140
constexpr float kSmoothTolerance = 5e-5f;    // one division (2.5 ulp) on h, scaled by |k| + |a - b| <= 200
constexpr float kDensityTolerance = 1e-6f;   // one division feeding a clamp to [0, 1]

const FunctionInfo kSdf[] = {
    {"sdf_sphere", "sdf_sphere(p: vec3, center: vec3, radius: float) -> float",
     "|p - center| - radius: exact signed distance (negative inside)", toFloat<Type::Vec3, Type::Vec3, Type::Float>,
     evalSphere, glslCall<kSphere>, kSdfLibs, kDistanceTolerance},
    {"sdf_box", "sdf_box(p: vec3, center: vec3, half_size: vec3) -> float",
     "exact Euclidean signed distance to the axis-aligned box center +- |half_size|",
     toFloat<Type::Vec3, Type::Vec3, Type::Vec3>, evalBox, glslCall<kBox>, kSdfLibs, kDistanceTolerance},
    {"sdf_capsule", "sdf_capsule(p: vec3, a: vec3, b: vec3, radius: float) -> float",
     "distance to the segment ab minus radius: exact signed distance (a == b: a sphere)",
     toFloat<Type::Vec3, Type::Vec3, Type::Vec3, Type::Float>, evalCapsule, glslCall<kCapsule>, kSdfLibs,
     kCapsuleTolerance},
    {"sdf_plane", "sdf_plane(p: vec3, normal: vec3, offset: float) -> float",
     "dot(p, normal / |normal|) - offset: exact signed distance, negative below (zero normal: -offset)",
     toFloat<Type::Vec3, Type::Vec3, Type::Float>, evalPlane, glslCall<kPlane>, kSdfLibs, kPlaneTolerance},
    {"sdf_heightfield", "sdf_heightfield(p: vec3, height: float) -> float",
     "p.y - height, height a 2D field of p.xz: negative below; a bound, not an exact distance",
     toFloat<Type::Vec3, Type::Float>, evalHeightfield, glslCall<kHeightfield>, kSdfLibs, kExact},
    {"sdf_union", "sdf_union(a: float, b: float) -> float", "min(a, b): inside either", toFloat<Type::Float, Type::Float>,
     evalUnion, unionGlsl, kMathLibrary, kExact},
    {"sdf_subtract", "sdf_subtract(a: float, b: float) -> float", "max(a, -b): a minus b",
     toFloat<Type::Float, Type::Float>, evalSubtract, subtractGlsl, kMathLibrary, kExact},
    {"sdf_intersect", "sdf_intersect(a: float, b: float) -> float", "max(a, b): inside both",
     toFloat<Type::Float, Type::Float>, evalIntersect, intersectGlsl, kMathLibrary, kExact},
    {"sdf_smooth_union", "sdf_smooth_union(a: float, b: float, k: float) -> float",
     "polynomial smooth min, blend radius k: mix(b, a, h) - k h (1 - h), h = clamp(0.5 + 0.5 (b - a) / k, 0, 1); "
     "in [min - k/4, min]; k <= 0: min(a, b)",
     toFloat<Type::Float, Type::Float, Type::Float>, evalSmooth<smoothUnion>, glslCall<kSmoothUnion>, kSdfLibs,
     kSmoothTolerance},
    {"sdf_smooth_subtract", "sdf_smooth_subtract(a: float, b: float, k: float) -> float",
     "smooth max(a, -b) = -sdf_smooth_union(-a, b, k); in [max, max + k/4]; k <= 0: max(a, -b)",
     toFloat<Type::Float, Type::Float, Type::Float>, evalSmooth<smoothSubtract>, glslCall<kSmoothSubtract>, kSdfLibs,
     kSmoothTolerance},
    {"sdf_smooth_intersect", "sdf_smooth_intersect(a: float, b: float, k: float) -> float",
     "smooth max(a, b) = -sdf_smooth_union(-a, -b, k); in [max, max + k/4]; k <= 0: max(a, b)",
     toFloat<Type::Float, Type::Float, Type::Float>, evalSmooth<smoothIntersect>, glslCall<kSmoothIntersect>, kSdfLibs,
     kSmoothTolerance},
    {"density", "density(d: float, width: float) -> float; density(d: float) -> float",
     "clamp(0.5 - d / width, 0, 1), width default 1: distance to grammar density, surface d = 0 -> 0.5, inside -> 1; "
     "width <= 0: step (1, 0.5, 0)",
     densityRule, evalDensity, densityGlsl, kSdfLibs, kDensityTolerance},
};

} // namespace

std::span<const FunctionInfo> sdfFunctions() { return kSdf; }

} // namespace voxc::function_records

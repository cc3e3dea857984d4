// Noise builtins: type rules, interpreter evaluation (Noise.h) and GLSL calls into the
// compiler/shaders/noise_*.glsl mirrors. Seeds are ints; their bit pattern is the uint seed.
#include "Noise.h"
#include "Records.h"

#include <algorithm>

namespace voxc::function_records {

namespace {

using noise::kWarpedFbmRoughness, noise::kWarpedFbmWarpHigh, noise::kWarpedFbmWarpLow;


template <Type R>
std::optional<Type> pointSeed(std::span<const Type> a) { // f(p: vec3, seed: int) -> R
    if (matches(a, {Type::Vec3, Type::Int})) return R;
    return std::nullopt;
}
std::optional<Type> fractalRule(std::span<const Type> a) {
    if (matches(a, {Type::Vec3, Type::Int, Type::Float, Type::Float, Type::Int})) return Type::Float;
    return std::nullopt;
}
std::optional<Type> warpRule(std::span<const Type> a) {
    if (matches(a, {Type::Vec3, Type::Float, Type::Int})) return Type::Vec3;
    return std::nullopt;
}
std::optional<Type> warpedFbmRule(std::span<const Type> a) {
    if (matches(a, {Type::Vec3, Type::Int}) || matches(a, {Type::Vec3, Type::Float, Type::Float, Type::Float, Type::Int}))
        return Type::Float;
    return std::nullopt;
}

uint32_t seedOf(const Value& v) { return uint32_t(v.i); }


constexpr char kPerlin3[] = "noisePerlin3", kSimplex3[] = "noiseSimplex3", kValue3[] = "noiseValue3",
               kWorley3[] = "noiseWorley3", kWorleyF1[] = "noiseWorleyF1", kWorleyF2[] = "noiseWorleyF2",
               kWorleyF2F1[] = "noiseWorleyF2F1", kCurl3[] = "noiseCurl3", kFbm[] = "noiseFbm",
               kRidged[] = "noiseRidged", kTurbulence[] = "noiseTurbulence", kWarp[] = "noiseWarp",
               kWarpedFbm[] = "noiseWarpedFbm";

constexpr std::string_view kPerlinLibs[] = {"random.glsl", "noise_common.glsl", "noise_permutation.glsl",
                                            "noise_perlin3.glsl"};
constexpr std::string_view kSimplexLibs[] = {"random.glsl", "noise_common.glsl", "noise_permutation.glsl",
                                             "noise_simplex3.glsl"};
constexpr std::string_view kValueLibs[] = {"random.glsl", "noise_common.glsl", "noise_value3.glsl"};
constexpr std::string_view kWorleyLibs[] = {"random.glsl", "noise_common.glsl", "noise_worley3.glsl"};
constexpr std::string_view kFractalLibs[] = {"random.glsl", "noise_common.glsl", "noise_permutation.glsl",
                                             "noise_perlin3.glsl", "noise_fractal.glsl"};

// Tolerances: add, subtract, multiply and floor are correctly rounded in Vulkan and every float
// result is `precise`, so these agree bit for bit; 1e-6 leaves room for denormal flushing.
constexpr float kLatticeTolerance = 1e-6f;
constexpr float kWorleyTolerance = 2e-6f;     // + one sqrt (results below ~2)
constexpr float kWorleyGapTolerance = 4e-6f;  // F2 - F1: two square roots
constexpr float kWarpedFbmTolerance = 1e-5f;  // one exp2 (3 + 2|x| ulp) scales the layer amplitudes

Value evalPerlin3(std::span<const Value> a) { return Value::makeFloat(noise::perlin3(a[0].v, seedOf(a[1]))); }
Value evalSimplex3(std::span<const Value> a) { return Value::makeFloat(noise::simplex3(a[0].v, seedOf(a[1]))); }
Value evalValue3(std::span<const Value> a) { return Value::makeFloat(noise::value3(a[0].v, seedOf(a[1]))); }
Value evalWorley3(std::span<const Value> a) { return Value::makeVec2(noise::worley3(a[0].v, seedOf(a[1]))); }
Value evalWorleyF1(std::span<const Value> a) { return Value::makeFloat(noise::worley3(a[0].v, seedOf(a[1])).x); }
Value evalWorleyF2(std::span<const Value> a) { return Value::makeFloat(noise::worley3(a[0].v, seedOf(a[1])).y); }
Value evalWorleyF2F1(std::span<const Value> a) {
    const glm::vec2 f = noise::worley3(a[0].v, seedOf(a[1]));
    return Value::makeFloat(f.y - f.x);
}
Value evalCurl3(std::span<const Value> a) { return Value::makeVec3(noise::curl3(a[0].v, seedOf(a[1]))); }
template <float (*F)(glm::vec3, int32_t, float, float, uint32_t)>
Value evalFractal(std::span<const Value> a) {
    return Value::makeFloat(F(a[0].v, a[1].i, a[2].v.x, a[3].v.x, seedOf(a[4])));
}
Value evalWarp(std::span<const Value> a) { return Value::makeVec3(noise::warp(a[0].v, a[1].v.x, seedOf(a[2]))); }
Value evalWarpedFbm(std::span<const Value> a) {
    if (a.size() == 2)
        return Value::makeFloat(
            noise::warpedFbm(a[0].v, kWarpedFbmRoughness, kWarpedFbmWarpLow, kWarpedFbmWarpHigh, seedOf(a[1])));
    return Value::makeFloat(noise::warpedFbm(a[0].v, a[1].v.x, a[2].v.x, a[3].v.x, seedOf(a[4])));
}

const FunctionInfo kNoise[] = {
    {"perlin3", "perlin3(p: vec3, seed: int) -> float",
     "Perlin's improved noise (2002), reference permutation; seed 0 = reference; 0 on lattice points; about [-1.04, 1.04]",
     pointSeed<Type::Float>, evalPerlin3, glslCall<kPerlin3>, kPerlinLibs, kLatticeTolerance},
    {"simplex3", "simplex3(p: vec3, seed: int) -> float",
     "3D simplex noise, kernel (0.5 - r^2)^4, Perlin's 12 gradients; about [-1, 1]", pointSeed<Type::Float>,
     evalSimplex3, glslCall<kSimplex3>, kSimplexLibs, kLatticeTolerance},
    {"value3", "value3(p: vec3, seed: int) -> float",
     "quintic interpolation of mix32-hashed lattice values; in [-1, 1)", pointSeed<Type::Float>, evalValue3,
     glslCall<kValue3>, kValueLibs, kLatticeTolerance},
    {"worley3", "worley3(p: vec3, seed: int) -> vec2",
     "(F1, F2): Euclidean distances to the nearest two feature points (one per cell, 27 cells); F1 <= F2, in [0, ~1.8]",
     pointSeed<Type::Vec2>, evalWorley3, glslCall<kWorley3>, kWorleyLibs, kWorleyTolerance},
    {"worley_f1", "worley_f1(p: vec3, seed: int) -> float", "worley3(p, seed).x: distance to the nearest feature point",
     pointSeed<Type::Float>, evalWorleyF1, glslCall<kWorleyF1>, kWorleyLibs, kWorleyTolerance},
    {"worley_f2", "worley_f2(p: vec3, seed: int) -> float", "worley3(p, seed).y: distance to the second-nearest feature point",
     pointSeed<Type::Float>, evalWorleyF2, glslCall<kWorleyF2>, kWorleyLibs, kWorleyTolerance},
    {"worley_f2f1", "worley_f2f1(p: vec3, seed: int) -> float", "F2 - F1 (cell borders at 0), >= 0",
     pointSeed<Type::Float>, evalWorleyF2F1, glslCall<kWorleyF2F1>, kWorleyLibs, kWorleyGapTolerance},
    {"curl3", "curl3(p: vec3, seed: int) -> vec3",
     "curl of three decorrelated perlin3 fields by central differences (eps 1/256); divergence-free up to discretisation",
     pointSeed<Type::Vec3>, evalCurl3, glslCall<kCurl3>, kFractalLibs, kLatticeTolerance},
    {"fbm", "fbm(p: vec3, octaves: int, lacunarity: float, gain: float, seed: int) -> float",
     "sum over k < clamp(octaves, 1, 16) of gain^k perlin3(p lacunarity^k, seed_k); |fbm| <= 1.04 sum gain^k",
     fractalRule, evalFractal<noise::fbm>, glslCall<kFbm>, kFractalLibs, kLatticeTolerance},
    {"ridged", "ridged(p: vec3, octaves: int, lacunarity: float, gain: float, seed: int) -> float",
     "sum of gain^k s_k, s_k = (1 - |n_k|)^2 w_k, w_0 = 1, w_k+1 = clamp(2 s_k, 0, 1); in [0, sum gain^k]",
     fractalRule, evalFractal<noise::ridged>, glslCall<kRidged>, kFractalLibs, kLatticeTolerance},
    {"turbulence", "turbulence(p: vec3, octaves: int, lacunarity: float, gain: float, seed: int) -> float",
     "sum of gain^k |n_k| (fbm's octaves folded); in [0, 1.04 sum gain^k]", fractalRule,
     evalFractal<noise::turbulence>, glslCall<kTurbulence>, kFractalLibs, kLatticeTolerance},
    {"warp", "warp(p: vec3, amount: float, seed: int) -> vec3",
     "p + amount * (three decorrelated fbm: 4 octaves, lacunarity 2, gain 0.5); |warp - p| <= 1.04 * 1.875 * |amount| per axis",
     warpRule, evalWarp, glslCall<kWarp>, kFractalLibs, kLatticeTolerance},
    {"warped_fbm",
     "warped_fbm(p: vec3, seed: int) -> float; warped_fbm(p: vec3, roughness: float, warp_low: float, warp_high: float, "
     "seed: int) -> float",
     "Mathisen Eq 3.11/3.12: sum k=0..4 of 2^(-k(1-R)) S(T(2^k p, k)), T(q, k) = q + (k F + D/(1+k)) (S(q+50), S(q+150), "
     "S(q+250)); short form R=0, D=1, F=0.5",
     warpedFbmRule, evalWarpedFbm, glslCall<kWarpedFbm>, kFractalLibs, kWarpedFbmTolerance},
};

} // namespace

std::span<const FunctionInfo> noiseFunctions() { return kNoise; }

} // namespace voxc::function_records

#include "voxc/generators/terrain/WarpedFbm2.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/Errors.h"

#include <array>
#include <cmath>

namespace voxc::terrain {

namespace {

// The builtin registry's perlin3, so the terrain noise is the very function field kernels call.
float perlin(float x, float y, uint32_t seed) {
    static const FunctionInfo* const perlin3 = findFunction("perlin3");
    VOXC_ASSERT(perlin3 != nullptr);
    const std::array<Value, 2> args{Value::makeVec3({x, y, 0.0f}), Value::makeInt(int32_t(seed))};
    return perlin3->eval(args).v.x;
}

// Layer k: q = 2^k p; w = k F + D / (1 + k); S(q + w (S(q + 50), S(q + 150))). `invOnePlusK` is a
// literal so no division runs (the same constants as the 3D warped_fbm).
float layer(float qx, float qy, float k, float invOnePlusK, float warpLow, float warpHigh, uint32_t seed) {
    const float w = k * warpHigh + warpLow * invOnePlusK;
    const float ox = perlin(qx + 50.0f, qy + 50.0f, seed);
    const float oy = perlin(qx + 150.0f, qy + 150.0f, seed);
    return perlin(qx + w * ox, qy + w * oy, seed);
}

} // namespace

float warpedFbm2(float x, float y, float roughness, float warpLow, float warpHigh, uint32_t seed) {
    // Layer weight r^(-k (1 - R)) = a^k with a = 2^-(1 - R), accumulated by products.
    const float a = std::exp2(-(1.0f - roughness));
    constexpr std::array<float, 5> kInvOnePlusK{1.0f, 0.5f, 0.333333343f, 0.25f, 0.2f};
    float sum = 0.0f, amplitude = 1.0f, scale = 1.0f;
    for (int k = 0; k < 5; ++k) {
        sum = sum + amplitude * layer(x * scale, y * scale, float(k), kInvOnePlusK[size_t(k)], warpLow, warpHigh, seed);
        amplitude = amplitude * a;
        scale = scale * 2.0f;
    }
    return sum;
}

} // namespace voxc::terrain

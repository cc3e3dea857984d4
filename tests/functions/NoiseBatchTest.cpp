// warpedFbmBatch equals the builtin's single-point evaluation bit for bit (its AVX2 and AVX-512 lanes run the
// same operations in the same order), over points at every scale the curves displacement uses,
// large and negative coordinates, every roughness, every tail length and non-finite inputs.
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/NoiseBatch.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace voxc {
namespace noise_batch_test {

float scalarWarpedFbm(float x, float y, float z, float roughness, float low, float high, uint32_t seed) {
    const FunctionInfo* f = findFunction("warped_fbm");
    const std::array<Value, 5> args{Value::makeVec3({x, y, z}), Value::makeFloat(roughness), Value::makeFloat(low),
                                    Value::makeFloat(high), Value::makeInt(int32_t(seed))};
    return f->eval(args).v.x;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(NoiseBatch, WarpedFbmEqualsTheBuiltinBitForBit) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float scales[] = {0.0625f, 1.0f, 40.0f, 3000.0f};
    const size_t n = 1027; // 128 registers of eight (64 of sixteen) and a tail of three
    for (uint32_t seed : {0u, 1u, 123456789u})
        for (float scale : scales) {
            std::vector<float> x(n), y(n), z(n), r(n), out(n);
            for (size_t i = 0; i < n; ++i) {
                x[i] = (unit(random) - 0.5f) * 2.0f * scale, y[i] = (unit(random) - 0.5f) * 2.0f * scale;
                z[i] = (unit(random) - 0.5f) * 2.0f * scale, r[i] = unit(random);
            }
            const float low = seed == 0 ? 0.0f : 0.7f, high = seed == 0 ? 0.0f : 0.35f;
            warpedFbmBatch(x.data(), y.data(), z.data(), r.data(), low, high, seed, n, out.data());
            size_t exact = 0;
            for (size_t i = 0; i < n; ++i) exact += sameBits(out[i], scalarWarpedFbm(x[i], y[i], z[i], r[i], low, high, seed));
            EXPECT_EQ(exact, n) << "seed " << seed << " scale " << scale;
            // Every short batch alone: up to 7 points in one padded register, 8-15 in one full
            // AVX2 register and a padded one (also where 1027 points take AVX-512 registers).
            for (size_t tail = 1; tail < 16; ++tail) {
                warpedFbmBatch(x.data(), y.data(), z.data(), r.data(), low, high, seed, tail, out.data());
                for (size_t i = 0; i < tail; ++i)
                    EXPECT_TRUE(sameBits(out[i], scalarWarpedFbm(x[i], y[i], z[i], r[i], low, high, seed)))
                        << "tail " << tail << " point " << i;
            }
        }
}

// The curves displacement's points: a box's cells times the noise frequency, so many on lattice
// planes (a fractional part of 0), in batches of every length a slice gives.
TEST(NoiseBatch, LatticeAlignedPointsEqualTheBuiltin) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const size_t n = 4096;
    for (uint32_t seed : {0u, 1u, 123456789u})
        for (float frequency : {0.125f, 0.03125f}) {
            std::vector<float> x(n), y(n), z(n), r(n), out(n);
            for (size_t i = 0; i < n; ++i) {
                x[i] = float(i % 64) * frequency, y[i] = float(i / 64 % 32) * frequency;
                z[i] = float(i / 2048 + 3) * frequency, r[i] = unit(random);
            }
            warpedFbmBatch(x.data(), y.data(), z.data(), r.data(), 0.0f, 0.0f, seed, n, out.data());
            size_t exact = 0;
            for (size_t i = 0; i < n; ++i) exact += sameBits(out[i], scalarWarpedFbm(x[i], y[i], z[i], r[i], 0.0f, 0.0f, seed));
            EXPECT_EQ(exact, n) << "seed " << seed << " frequency " << frequency;
        }
}

TEST(NoiseBatch, NonFiniteLanesAreNaNLikeTheBuiltin) {
    std::vector<float> x(16, 1.5f), y(16, -2.25f), z(16, 3.0f), r(16, 0.5f), out(16);
    x[1] = INFINITY, y[6] = -INFINITY, z[9] = NAN;
    warpedFbmBatch(x.data(), y.data(), z.data(), r.data(), 0.0f, 0.0f, 5u, 16, out.data());
    for (size_t i = 0; i < 16; ++i) {
        const float expected = scalarWarpedFbm(x[i], y[i], z[i], r[i], 0.0f, 0.0f, 5u);
        EXPECT_EQ(std::isnan(out[i]), std::isnan(expected)) << i;
        if (!std::isnan(expected)) {
            EXPECT_TRUE(sameBits(out[i], expected)) << i;
        }
    }
    EXPECT_TRUE(std::isnan(out[1]) && std::isnan(out[6]) && std::isnan(out[9]));
}

} // namespace noise_batch_test
} // namespace voxc

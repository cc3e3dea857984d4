// The host's field rows (voxc::FieldRowEvaluator, the fractal row of voxc/builtins/NoiseRow.h)
// against the point-wise evaluator and the builtins, voxel by voxel: every path of the row (uniform nodes, row
// loops, the fractal row's table, its one-cell and fallback blocks, its point-by-point rows, the
// record's eval lane by lane) gives the same bits. ctest runs this binary under each VOXC_SIMD.
#include "CheckedProgram.h"
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/NoiseRow.h"
#include "voxc/core/Simd.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/interp/FieldRows.h"
#include "voxc/program/Semantics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace voxc {
namespace field_rows_test {

// The same value: equal bits, or both NaN (a NaN's payload is not specified; stages store 0).
bool same(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b) || (std::isnan(a) && std::isnan(b)); }

// Fields over rows of 300 voxels (a full row of 256 and a rest of 44), at two origins and local bases.
struct Frame {
    std::string world;
    glm::ivec3 localBase;
};

const Frame kFrames[] = {
    {"world { size = [300, 3, 2]; origin = [-150, 7, -3]; }\n", glm::ivec3(0)},
    {"world { size = [300, 2, 2]; origin = [16777000, -40000, 123]; }\n", glm::ivec3(-37, 5, 11)},
};

const char* const kFields[] = {
    // The fractal row: wp's y and z are the same along a row.
    "fbm(wp * 0.02, 5, 2.0, 0.5, 0)",
    "turbulence(p * 0.11 + vec3(0.5, 0.25, 0.0), 4, 2.0, 0.5, 7)",
    "ridged(wp * 0.05, 3, 1.9, 0.6, 3)",
    "perlin3(vec3(x * 0.3, y * 0.1, 4.0), 2)",
    "fbm(vec3(-x * 0.07, y * 0.2, z), 4, 2.0, 0.5, 11)",        // x decreasing along the row
    "fbm(vec3(x * 1.3, y, z), 3, 2.0, 0.5, 1)",                  // cells under a voxel: fallback blocks
    "fbm(vec3(x * 3.7, y, z), 3, 2.0, 0.5, 1)",                  // many cells per point: point by point
    "perlin3(vec3(x * 100000.0, y, z), 5)",                      // floors past 2^24: point by point
    "perlin3(vec3(x * 0.5, 1.0e30, z), 5)",                      // y past 2^24
    "fbm(vec3(x / (x - 10), y, z), 2, 2.0, 0.5, 0)",             // an infinite x
    "perlin3(vec3((x - 5) / (x - 5) * x, y, z) * 0.2, 0)",       // a NaN x
    "fbm(vec3(x, y / 0, z) * 0.1, 3, 2.0, 0.5, 0)",              // y not finite: the whole row NaN
    "fbm(wp * 0.02, 3, -2.0, 0.5, 0)",                           // negative frequencies
    "fbm(wp * 0.02, 3, 0.0, 0.5, 0)",                            // zero frequencies
    "fbm(wp * 0.02, 0, 2.0, 0.5, 0) + fbm(wp * 0.013, 40, 2.0, 0.5, 9)", // octaves clamped to 1..16
    "fbm(wp * 0.02 + vec3(0.0, 0.0, -0.0), 3, 2.0, 0.5, -4)",
    "perlin3(vec3(x * 0.25, 0.0, -0.0), 3) + perlin3(vec3(x * 0.25, -0.0, 2.0), 3)", // lattice-exact y, z
    // Not the fractal row: y varies along the row.
    "fbm(vec3(x, x * 0.5, z) * 0.05, 3, 2.0, 0.5, 0)",
    "perlin3(vec3(0.5 * x, 7.25, -3.5), 9) * fbm(vec3(y, z, x) * 0.1, 2, 2.0, 0.5, 4)",
    // Row loops, uniform components and record evaluations lane by lane.
    "let q = wp * 0.03 in max(q.x, q.z) - min(q.y, 1.0)",
    "length(p - vec3(10, 1, 1)) - 5.0 + abs(sin(x * 0.1)) * fract(wz * 0.37)",
    "x < 4 && !(y == 1) ? 1.0 : -x / 3.0",
    "-(p * 2).x / 3.0 + (vec3(1, 2, 3) / p).y",
    "clamp(mix(x, y, 0.5), 0, 1) + length((p * 0.5).xz) - 3.0",
    "simplex3(wp * 0.04, 1) + value3(wp * 0.07, 2) + worley_f1(wp * 0.05, 3)",
    "warped_fbm(wp * 0.01, 5) * 0.5",
    "(wp * 0.5).x",
    "wy * 0.5 + wz",
    "1.5",
};

TEST(interp_FieldRows, EveryVoxelEqualsThePointwiseEvaluator) {
    for (const Frame& frame : kFrames)
        for (const char* expression : kFields) {
            SCOPED_TRACE(std::string(expression) + " in " + frame.world);
            const Program program = test::checkedProgram("rows.vox", frame.world + "field f = " + expression + ";\n");
            ASSERT_FALSE(program.fields.empty());
            const Field& field = program.fields.back();
            FieldEvaluator pointwise(field, program.world.origin, frame.localBase);
            FieldRowEvaluator rows(field, program.world.origin, frame.localBase);
            const glm::ivec3 size = program.world.size;
            int differing = 0;
            for (int z = 0; z < size.z; ++z)
                for (int y = 0; y < size.y; ++y)
                    for (int x0 = 0; x0 < size.x; x0 += FieldRowEvaluator::kRowVoxels) {
                        const int count = std::min(FieldRowEvaluator::kRowVoxels, size.x - x0);
                        float row[FieldRowEvaluator::kRowVoxels];
                        rows.evaluate({x0, y, z}, count, row);
                        for (int i = 0; i < count; ++i) {
                            const float expected = pointwise.density({x0 + i, y, z});
                            if (!same(row[i], expected) && differing++ < 3)
                                ADD_FAILURE() << "voxel (" << x0 + i << ", " << y << ", " << z << "): row " << row[i]
                                              << ", point " << expected << " (VOXC_SIMD path " << simdName(hostSimd()) << ")";
                        }
                    }
            EXPECT_EQ(differing, 0);
        }
}

// runField over the host's threads: every mode's combination and the non-finite count as one
// thread voxel by voxel gives them.
TEST(interp_FieldRows, FieldStagesEqualTheVoxelByVoxelCombination) {
    const std::string source = "world { size = [70, 9, 13]; origin = [3, -2, 5]; }\n"
                               "material rock { id = 1; color = [0.5, 0.5, 0.5]; }\n"
                               "field ground = fbm(wp * 0.08, 3, 2.0, 0.5, 2) + 0.1 * (4 - y);\n"
                               "field hole = (x - 30) / (x - 30) * perlin3(wp * 0.2, 1);\n"
                               "pipeline { start; set ground; union hole material rock; subtract ground; "
                               "intersect hole; paint ground material rock; }\n";
    const Program program = test::checkedProgram("stages.vox", source);
    DenseGrid rows(program.world.size), expected(program.world.size);
    for (const Stage& stage : program.pipeline) {
        if (stage.kind != Stage::Kind::Field) continue;
        NonFiniteCount rowCount, expectedCount;
        runField(program, stage, rows, &rowCount);
        FieldEvaluator evaluator(program.fields[stage.index], program.world.origin, program.world.localBase);
        const glm::ivec3 size = program.world.size;
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    const glm::ivec3 v{x, y, z};
                    const float f = expectedCount.replace(evaluator.density(v), expected.index(v));
                    const VoxelState voxel =
                        combineField(stage.mode, stage.material, f, {expected.at(v), expected.materialAt(v)});
                    expected.at(v) = voxel.density;
                    expected.materialAt(v) = voxel.material;
                }
        EXPECT_EQ(rowCount.count, expectedCount.count) << stage.label;
        EXPECT_EQ(rowCount.firstIndex, expectedCount.firstIndex) << stage.label;
    }
    EXPECT_EQ(rows.data(), expected.data());
    EXPECT_EQ(rows.materials(), expected.materials());
    EXPECT_GT(std::count(rows.materials().begin(), rows.materials().end(), uint8_t(1)), 0);
}

// The builtin's value at one point, by its record.
float builtin(FractalFold fold, float x, float y, float z, int32_t octaves, float lacunarity, float gain, uint32_t seed) {
    const Value p = Value::makeVec3({x, y, z}), s = Value::makeInt(int32_t(seed));
    if (fold == FractalFold::Sum && octaves == 1) return findFunction("perlin3")->eval(std::vector<Value>{p, s}).v.x;
    const char* name = fold == FractalFold::Sum ? "fbm" : fold == FractalFold::Absolute ? "turbulence" : "ridged";
    return findFunction(name)
        ->eval(std::vector<Value>{p, Value::makeInt(octaves), Value::makeFloat(lacunarity), Value::makeFloat(gain), s})
        .v.x;
}

// Points on and halfway between lattice planes, signed zeros included: there a gradient's part
// or the noise itself is a zero whose sign only exact operations keep.
TEST(interp_FieldRows, LatticePointsKeepTheBuiltinsSignedZeros) {
    std::vector<float> x;
    for (int i = -40; i <= 40; ++i) x.push_back(float(i) * 0.5f);
    x.push_back(-0.0f);
    std::vector<float> out(x.size());
    FractalRow row;
    int differing = 0;
    for (uint32_t seed = 0; seed < 48; ++seed)
        for (float y : {0.0f, -0.0f, 1.0f, -3.0f, 0.5f})
            for (float z : {0.0f, -0.0f, 2.0f, -0.5f})
                for (FractalFold fold : {FractalFold::Sum, FractalFold::Absolute, FractalFold::Ridged})
                    for (int32_t octaves : {1, 3}) {
                        row.evaluate(fold, x.data(), y, z, octaves, 2.0f, 0.5f, seed, x.size(), out.data());
                        for (size_t i = 0; i < x.size(); ++i) {
                            const float expected = builtin(fold, x[i], y, z, octaves, 2.0f, 0.5f, seed);
                            if (std::bit_cast<uint32_t>(out[i]) != std::bit_cast<uint32_t>(expected) && differing++ < 3)
                                ADD_FAILURE() << "seed " << seed << " at (" << x[i] << ", " << y << ", " << z
                                              << "): row " << out[i] << ", builtin " << expected;
                        }
                    }
    EXPECT_EQ(differing, 0);
}

// Random rows: increasing, decreasing and shuffled x at every scale, every row length up to 300.
TEST(interp_FieldRows, RandomRowsEqualTheBuiltin) {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    FractalRow row;
    int differing = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const size_t n = 1 + size_t(trial);
        const float step = std::pow(10.0f, unit(random) * 4.0f - 3.0f) * (trial % 3 == 1 ? -1.0f : 1.0f);
        const float start = (unit(random) - 0.5f) * 2000.0f;
        std::vector<float> x(n), out(n);
        for (size_t i = 0; i < n; ++i) x[i] = start + float(i) * step;
        if (trial % 3 == 2) std::shuffle(x.begin(), x.end(), random);
        const float y = (unit(random) - 0.5f) * 500.0f, z = (unit(random) - 0.5f) * 500.0f;
        const FractalFold fold = FractalFold(trial % 3);
        const int32_t octaves = 1 + trial % 6;
        const float lacunarity = 1.5f + unit(random), gain = unit(random);
        const uint32_t seed = uint32_t(random());
        row.evaluate(fold, x.data(), y, z, octaves, lacunarity, gain, seed, n, out.data());
        for (size_t i = 0; i < n; ++i) {
            const float expected = builtin(fold, x[i], y, z, octaves, lacunarity, gain, seed);
            if (std::bit_cast<uint32_t>(out[i]) != std::bit_cast<uint32_t>(expected) && differing++ < 3)
                ADD_FAILURE() << "trial " << trial << " point " << i << ": row " << out[i] << ", builtin " << expected;
        }
    }
    EXPECT_EQ(differing, 0);
}

} // namespace field_rows_test
} // namespace voxc

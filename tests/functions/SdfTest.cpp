// Signed distance builtins through the registry's interpreter evaluation: exact distances at
// known points and against a double-precision reference, Lipschitz-1 and unit gradients for the
// exact SDFs, CSG identities and the smooth variants' bounds, and the `density` bridge to the
// grammar's GEQ 0.5 threshold (the GPU side is GpuAgreementTest's job).
#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace voxc {
namespace sdf_test {

float call(std::string_view name, std::vector<Value> args) {
    const FunctionInfo* f = findFunction(name);
    if (!f) throw std::runtime_error("no function " + std::string(name));
    return f->eval(args).v.x;
}
Value v3(glm::vec3 p) { return Value::makeVec3(p); }
Value f(float x) { return Value::makeFloat(x); }

float sphere(glm::vec3 p, glm::vec3 c, float r) { return call("sdf_sphere", {v3(p), v3(c), f(r)}); }
float box(glm::vec3 p, glm::vec3 c, glm::vec3 h) { return call("sdf_box", {v3(p), v3(c), v3(h)}); }
float capsule(glm::vec3 p, glm::vec3 a, glm::vec3 b, float r) { return call("sdf_capsule", {v3(p), v3(a), v3(b), f(r)}); }
float plane(glm::vec3 p, glm::vec3 n, float o) { return call("sdf_plane", {v3(p), v3(n), f(o)}); }

std::vector<glm::vec3> randomPoints(size_t count, float extent, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-extent, extent);
    std::vector<glm::vec3> points(count);
    for (glm::vec3& p : points) p = {u(rng), u(rng), u(rng)};
    return points;
}

TEST(functions_Sdf, PrimitivesAtKnownPoints) {
    const glm::vec3 c(1, 2, 3);
    EXPECT_FLOAT_EQ(sphere(c, c, 2), -2.0f);
    EXPECT_FLOAT_EQ(sphere({4, 2, 3}, c, 2), 1.0f);
    EXPECT_FLOAT_EQ(sphere({1, 2, 5}, c, 2), 0.0f);

    const glm::vec3 h(1, 2, 3);
    EXPECT_FLOAT_EQ(box({0, 0, 0}, {0, 0, 0}, h), -1.0f); // nearest face is x = +-1
    EXPECT_FLOAT_EQ(box({0.5f, 0, 0}, {0, 0, 0}, h), -0.5f);
    EXPECT_FLOAT_EQ(box({3, 0, 0}, {0, 0, 0}, h), 2.0f);
    EXPECT_FLOAT_EQ(box({2, 3, 0}, {0, 0, 0}, h), std::sqrt(2.0f)); // off an edge
    EXPECT_FLOAT_EQ(box({2, 3, 4}, {0, 0, 0}, h), std::sqrt(3.0f)); // off a corner
    EXPECT_FLOAT_EQ(box({11, 20, 30}, {10, 20, 30}, h), 0.0f);
    EXPECT_EQ(box({2, 3, 4}, {0, 0, 0}, -h), box({2, 3, 4}, {0, 0, 0}, h));

    const glm::vec3 a(0, 0, 0), b(0, 4, 0);
    EXPECT_FLOAT_EQ(capsule({3, 2, 0}, a, b, 1), 2.0f);  // beside the segment
    EXPECT_FLOAT_EQ(capsule({0, 2, 0}, a, b, 1), -1.0f); // on the axis
    EXPECT_FLOAT_EQ(capsule({0, -2, 0}, a, b, 1), 1.0f); // beyond end a
    EXPECT_FLOAT_EQ(capsule({0, 7, 0}, a, b, 1), 2.0f);  // beyond end b
    EXPECT_FLOAT_EQ(capsule({3, 4, 4}, a, a, 1), sphere({3, 4, 4}, a, 1)); // degenerate: a sphere

    EXPECT_FLOAT_EQ(plane({7, 8, -1}, {0, 2, 0}, 5), 3.0f); // the normal is normalised
    EXPECT_FLOAT_EQ(plane({7, 1, -1}, {0, 2, 0}, 5), -4.0f);
    EXPECT_NEAR(plane({1, 0, 0}, {1, 1, 0}, 0), std::sqrt(0.5f), 1e-7f);
    EXPECT_EQ(plane({1, 2, 3}, {0, 0, 0}, 5), -5.0f);

    EXPECT_EQ(call("sdf_heightfield", {v3({3, 10, 4}), f(12.5f)}), -2.5f);
    EXPECT_EQ(call("sdf_heightfield", {v3({3, 14, 4}), f(12.5f)}), 1.5f);
}

// Distances to the sphere, box and capsule computed in double from their definitions.
double referenceBox(glm::dvec3 p, glm::dvec3 c, glm::dvec3 h) {
    const glm::dvec3 d = glm::abs(p - c);
    if (d.x <= h.x && d.y <= h.y && d.z <= h.z) return -std::min({h.x - d.x, h.y - d.y, h.z - d.z});
    return glm::length(glm::max(d - h, 0.0));
}
double referenceCapsule(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, double r) {
    const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::length(p - (a + t * (b - a))) - r;
}

TEST(functions_Sdf, ExactDistancesMatchADoubleReference) {
    const glm::vec3 c(3, -2, 5), h(4, 1.5f, 7), a(-3, 1, 2), b(6, -4, 9);
    for (const glm::vec3 p : randomPoints(20000, 20, 3)) {
        EXPECT_NEAR(sphere(p, c, 6), glm::length(glm::dvec3(p) - glm::dvec3(c)) - 6.0, 1e-5);
        EXPECT_NEAR(box(p, c, h), referenceBox(p, c, h), 1e-5);
        EXPECT_NEAR(capsule(p, a, b, 2.5f), referenceCapsule(p, a, b, 2.5), 1e-5);
        EXPECT_NEAR(plane(p, {1, -2, 2}, 1.5f), glm::dot(glm::dvec3(p), glm::dvec3(1, -2, 2)) / 3.0 - 1.5, 1e-5);
    }
}

using Sdf = std::function<float(glm::vec3)>;

std::vector<std::pair<std::string, Sdf>> exactSdfs() {
    return {
        {"sphere", [](glm::vec3 p) { return sphere(p, {1, 2, 3}, 5); }},
        {"box", [](glm::vec3 p) { return box(p, {-2, 1, 0}, {3, 6, 2}); }},
        {"capsule", [](glm::vec3 p) { return capsule(p, {-4, 0, 1}, {5, 3, -2}, 1.5f); }},
        {"plane", [](glm::vec3 p) { return plane(p, {0.3f, 1, -0.5f}, 2); }},
    };
}

TEST(functions_Sdf, ExactDistancesAreLipschitzOneWithUnitGradient) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> step(-1.0f, 1.0f);
    for (const auto& [name, sdf] : exactSdfs()) {
        int unitGradients = 0;
        const std::vector<glm::vec3> points = randomPoints(5000, 15, 4);
        for (const glm::vec3 p : points) {
            for (float scale : {0.01f, 1.0f, 10.0f}) {
                const glm::vec3 q = p + scale * glm::vec3(step(rng), step(rng), step(rng));
                const float bound = glm::distance(p, q) * (1 + 1e-5f) + 2e-5f;
                ASSERT_LE(std::fabs(sdf(p) - sdf(q)), bound) << name << " at " << p.x << "," << p.y << "," << p.z;
            }
            // Off the medial surfaces an exact distance has |gradient| = 1.
            const float e = 1.0f / 64;
            const glm::vec3 gradient(sdf(p + glm::vec3(e, 0, 0)) - sdf(p - glm::vec3(e, 0, 0)),
                                     sdf(p + glm::vec3(0, e, 0)) - sdf(p - glm::vec3(0, e, 0)),
                                     sdf(p + glm::vec3(0, 0, e)) - sdf(p - glm::vec3(0, 0, e)));
            unitGradients += std::fabs(glm::length(gradient) / (2 * e) - 1.0f) < 1e-2f;
        }
        EXPECT_GT(unitGradients, int(points.size()) * 95 / 100) << name;
    }
}

TEST(functions_Sdf, HardCsgIdentities) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-100.0f, 100.0f);
    for (int n = 0; n < 10000; ++n) {
        const float a = u(rng), b = u(rng);
        EXPECT_EQ(call("sdf_union", {f(a), f(b)}), call("sdf_union", {f(b), f(a)}));
        EXPECT_EQ(call("sdf_union", {f(a), f(b)}), std::min(a, b));
        EXPECT_EQ(call("sdf_intersect", {f(a), f(b)}), call("sdf_intersect", {f(b), f(a)}));
        EXPECT_EQ(call("sdf_intersect", {f(a), f(b)}), std::max(a, b));
        EXPECT_EQ(call("sdf_subtract", {f(a), f(b)}), call("sdf_intersect", {f(a), f(-b)}));
    }
    // A sphere minus a smaller concentric one is a shell: negative between the radii only.
    const auto shell = [](glm::vec3 p) {
        return call("sdf_subtract", {f(sphere(p, {0, 0, 0}, 5)), f(sphere(p, {0, 0, 0}, 3))});
    };
    EXPECT_GT(shell({0, 0, 0}), 0.0f);
    EXPECT_LT(shell({4, 0, 0}), 0.0f);
    EXPECT_GT(shell({6, 0, 0}), 0.0f);
}

TEST(functions_Sdf, SmoothCsgBoundsAndLimits) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(-20.0f, 20.0f), radius(0.0f, 8.0f);
    for (int n = 0; n < 20000; ++n) {
        const float a = u(rng), b = u(rng), k = radius(rng);
        const float lo = std::min(a, b), hi = std::max(a, b);
        const float slack = 1e-5f * (1 + std::fabs(lo) + std::fabs(hi) + k); // a few roundings
        const float su = call("sdf_smooth_union", {f(a), f(b), f(k)});
        EXPECT_LE(su, lo + slack);
        EXPECT_GE(su, lo - k / 4 - slack);
        EXPECT_NEAR(su, call("sdf_smooth_union", {f(b), f(a), f(k)}), slack);
        if (hi - lo >= k) {
            EXPECT_EQ(su, lo) << "outside the blend band the union is hard";
        }
        const float si = call("sdf_smooth_intersect", {f(a), f(b), f(k)});
        EXPECT_GE(si, hi - slack);
        EXPECT_LE(si, hi + k / 4 + slack);
        EXPECT_EQ(call("sdf_smooth_subtract", {f(a), f(b), f(k)}), call("sdf_smooth_intersect", {f(a), f(-b), f(k)}));
    }
    // The deepest blend, k/4, is where the operands are equal; k -> 0 tends to the hard operations.
    EXPECT_EQ(call("sdf_smooth_union", {f(1), f(1), f(2)}), 0.5f);
    for (float k : {1.0f, 0.1f, 0.01f, 0.001f}) {
        float worst = 0;
        for (int n = 0; n < 2000; ++n) {
            const float a = u(rng), b = a + k * u(rng) / 10;
            worst = std::max(worst, std::fabs(call("sdf_smooth_union", {f(a), f(b), f(k)}) - std::min(a, b)));
        }
        EXPECT_LE(worst, k / 4 + 1e-5f) << k;
    }
    for (float k : {0.0f, -1.0f}) {
        EXPECT_EQ(call("sdf_smooth_union", {f(2), f(3), f(k)}), 2.0f);
        EXPECT_EQ(call("sdf_smooth_intersect", {f(2), f(3), f(k)}), 3.0f);
        EXPECT_EQ(call("sdf_smooth_subtract", {f(2), f(3), f(k)}), 2.0f);
    }
}

float density(float d, float width) { return call("density", {f(d), f(width)}); }

TEST(functions_Sdf, DensityBridgesDistancesToTheGrammarThreshold) {
    for (float w : {0.25f, 1.0f, 3.0f, 16.0f}) {
        EXPECT_EQ(density(0, w), 0.5f) << w;
        EXPECT_EQ(density(-w / 2, w), 1.0f) << w;
        EXPECT_EQ(density(w / 2, w), 0.0f) << w;
        EXPECT_EQ(density(-10 * w, w), 1.0f) << w;
        EXPECT_EQ(density(10 * w, w), 0.0f) << w;
        float previous = 1.0f;
        for (float d = -w; d <= w; d += w / 97) { // monotone non-increasing
            EXPECT_LE(density(d, w), previous) << w << " " << d;
            previous = density(d, w);
        }
    }
    EXPECT_EQ(density(0.25f, 1), 0.25f);
    EXPECT_EQ(call("density", {f(0.25f)}), 0.25f);
    EXPECT_EQ(call("density", {f(-0.3f)}), density(-0.3f, 1));
    for (float w : {0.0f, -2.0f}) { // the step it tends to
        EXPECT_EQ(density(-0.1f, w), 1.0f);
        EXPECT_EQ(density(0.0f, w), 0.5f);
        EXPECT_EQ(density(0.1f, w), 0.0f);
    }
}

// A generated terrain: fbm heights as an SDF, turned into densities; the grammar's GEQ 0.5 holds
// exactly on and below the surface (a point outside by less than ~1e-7 width reads as surface).
TEST(functions_Sdf, GrammarThresholdSeesTheSurfaceOfAGeneratedTerrain) {
    const SymbolOpInfo& geq = symbolOpInfo(*findSymbolOp("GEQ"));
    for (float w : {1.0f, 2.0f}) {
        int rock = 0, air = 0;
        for (int x = 0; x < 32; ++x)
            for (int z = 0; z < 32; ++z) {
                const float fbm = call("fbm", {v3({x * 0.05f, 0, z * 0.05f}), Value::makeInt(4), f(2), f(0.5f),
                                               Value::makeInt(7)});
                const float height = 16 + 8 * fbm;
                for (int y = 0; y < 32; ++y) {
                    const float d = call("sdf_heightfield", {v3({float(x), float(y), float(z)}), f(height)});
                    const bool solid = geq.eval(density(d, w), 0.5f);
                    EXPECT_EQ(solid, float(y) <= height) << x << "," << y << "," << z;
                    (solid ? rock : air)++;
                }
            }
        EXPECT_GT(rock, 0);
        EXPECT_GT(air, 0);
    }
}

} // namespace sdf_test
} // namespace voxc

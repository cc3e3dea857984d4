// The curves solve's other passes on lavapipe (voxc/vulkan/GpuCurves.h) against the host loops,
// the reference: Perona-Malik sweeps, binomial smoothing, the material and surface fronts bit for
// bit, the noise displacement within warped_fbm's tolerance, on boxes that are odd, flat, offset
// and small; then a whole curves solve with every pass on the device gives the host's channels.
// The validation layer stays quiet.
#include "../curves/Scenes.h"
#include "Lavapipe.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/GpuCurves.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

namespace voxc {
namespace {

using test::expectNoValidationMessages;

size_t bitDifferences(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += std::bit_cast<uint32_t>(a[i]) != std::bit_cast<uint32_t>(b[i]);
    return n;
}

struct TestBox {
    glm::ivec3 min, size;
};
// Odd, flat (an axis of 3), offset and small boxes; the cliff scene meets each.
constexpr TestBox kBoxes[] = {{{0, 0, 0}, {64, 32, 64}}, {{3, 5, 2}, {37, 19, 45}}, {{0, 12, 0}, {64, 3, 64}},
                              {{10, 10, 20}, {7, 5, 6}}};

std::string describe(const TestBox& b) {
    return fmt::format("box {}x{}x{} at {},{},{}", b.size.x, b.size.y, b.size.z, b.min.x, b.min.y, b.min.z);
}

curves::Constraints cliffConstraints(const TestBox& b) {
    return curves::voxelize(curves::test::cliffScene(), curves::Box{b.min, b.size}, curves::SeedValue::PlaneDistance,
                            curves::Limits{});
}

// Normalised laplace normals of the constraints, the fronts' input (host: the reference solve).
std::array<curves::Field3, 3> unitNormals(const curves::Constraints& cs) {
    curves::Field3 x = cs.normalX, y = cs.normalY, z = cs.normalZ;
    std::vector<uint8_t> fixed(cs.flags.size());
    for (size_t i = 0; i < fixed.size(); ++i) fixed[i] = (cs.flags[i] & curves::kInNormals) ? 1 : 0;
    curves::solveLaplace("normals", fixed, {&x, &y, &z}, 1e-5f, curves::Limits{});
    std::array<curves::Field3, 3> unit;
    curves::normalizeField(x, y, z, unit[0], unit[1], unit[2]);
    return unit;
}

TEST(vulkan_GpuCurves, PeronaMalikSweepsMatchTheHost) {
    for (const TestBox& b : kBoxes) {
        SCOPED_TRACE(describe(b));
        const curves::Constraints cs = cliffConstraints(b);
        const curves::NormalField filled = curves::peronaMalikFill(cs);
        for (uint32_t sweeps : {1u, 2u, 9u}) {
            SCOPED_TRACE(fmt::format("{} sweeps", sweeps));
            curves::NormalField host = filled, device = filled;
            curves::peronaMalikSweeps(cs, host, 0.01f, sweeps);
            vulkanPeronaMalikSweeps(test::validatedLavapipe(), cs, device, 0.01f, sweeps);
            EXPECT_EQ(bitDifferences(host.x.values, device.x.values) + bitDifferences(host.y.values, device.y.values) +
                          bitDifferences(host.z.values, device.z.values),
                      0u);
            EXPECT_EQ(host.set, device.set);
        }
    }
    expectNoValidationMessages();
}

TEST(vulkan_GpuCurves, SmoothingMatchesTheHost) {
    for (const TestBox& b : kBoxes) {
        SCOPED_TRACE(describe(b));
        const curves::Constraints cs = cliffConstraints(b);
        const auto n = unitNormals(cs);
        // The raw surface, +infinity where no seed reaches (so infinities pass through the stencil too).
        const curves::Field3 raw =
            curves::propagateSurface(cs, n[0], n[1], n[2], curves::PropagateRule::SmallestMagnitude).distance;
        for (int32_t passes : {0, 1, 3}) {
            SCOPED_TRACE(fmt::format("{} passes", passes));
            EXPECT_EQ(bitDifferences(curves::smoothBinomial(raw, passes).values,
                                     vulkanSmoothBinomial(test::validatedLavapipe(), raw, passes).values),
                      0u);
        }
    }
    expectNoValidationMessages();
}

TEST(vulkan_GpuCurves, FrontsMatchTheHost) {
    for (const TestBox& b : kBoxes) {
        SCOPED_TRACE(describe(b));
        const curves::Constraints cs = cliffConstraints(b);
        const curves::MaterialField hostMaterial = curves::propagateMaterial(cs);
        const curves::MaterialField deviceMaterial = vulkanPropagateMaterial(test::validatedLavapipe(), cs);
        EXPECT_EQ(hostMaterial.material, deviceMaterial.material);
        EXPECT_EQ(hostMaterial.assigned, deviceMaterial.assigned);
        EXPECT_EQ(bitDifferences(hostMaterial.confidence.values, deviceMaterial.confidence.values), 0u);
        EXPECT_EQ(hostMaterial.layers, deviceMaterial.layers);
        EXPECT_GT(hostMaterial.layers, 1);

        const auto n = unitNormals(cs);
        for (curves::PropagateRule rule : {curves::PropagateRule::SmallestMagnitude, curves::PropagateRule::SignedMin}) {
            SCOPED_TRACE(rule == curves::PropagateRule::SignedMin ? "signed min" : "smallest magnitude");
            const curves::SurfaceField host = curves::propagateSurface(cs, n[0], n[1], n[2], rule);
            const curves::SurfaceField device = vulkanPropagateSurface(test::validatedLavapipe(), cs, n[0], n[1], n[2], rule);
            EXPECT_EQ(bitDifferences(host.distance.values, device.distance.values), 0u);
            EXPECT_EQ(host.layer, device.layer);
            EXPECT_EQ(host.layers, device.layers);
        }
    }
    expectNoValidationMessages();
}

// A box no seed reaches: the front is empty from the start, every cell stays +infinity.
TEST(vulkan_GpuCurves, EmptyFrontLeavesTheBoxUnreached) {
    const TestBox far{{200, 200, 200}, {9, 4, 5}};
    const curves::Constraints cs = cliffConstraints(far);
    const curves::Field3 zero(cs.box);
    const curves::SurfaceField device =
        vulkanPropagateSurface(test::validatedLavapipe(), cs, zero, zero, zero, curves::PropagateRule::SmallestMagnitude);
    for (float v : device.distance.values) EXPECT_EQ(v, INFINITY);
    EXPECT_EQ(device.layers, 0);
    EXPECT_EQ(vulkanPropagateMaterial(test::validatedLavapipe(), cs).layers, 0);
    expectNoValidationMessages();
}

// The whole solve with every pass on the device: every channel the host's bit for bit, but the
// displacement (warped_fbm's exp2) within the builtin's tolerance, 1e-5 per unit of amplitude.
TEST(vulkan_GpuCurves, WholeSolveMatchesTheHost) {
    for (curves::NormalMode mode : {curves::NormalMode::Laplace, curves::NormalMode::PeronaMalik}) {
        for (const TestBox& b : {kBoxes[0], kBoxes[1]}) {
            SCOPED_TRACE(describe(b) + (mode == curves::NormalMode::Laplace ? " laplace" : " perona_malik"));
            curves::Scene scene;
            scene.curves = curves::test::cliffScene();
            scene.box = curves::Box{b.min, b.size};
            scene.options.normals = mode;
            scene.options.sweeps = 12;
            scene.noiseSeed = 7;
            const SolveTable host = curves::solveScene(scene, curves::Limits{}, {}, true);
            const SolveTable device =
                curves::solveScene(scene, curves::Limits{}, vulkanCurvesSolvers([] { return &test::validatedLavapipe(); }), true);
            ASSERT_EQ(host.channels.size(), device.channels.size());
            for (size_t c = 0; c < host.channels.size(); ++c) {
                SCOPED_TRACE(host.channels[c].first);
                const std::vector<float>& h = host.channels[c].second;
                const std::vector<float>& d = device.channels[c].second;
                if (host.channels[c].first != "displacement") {
                    EXPECT_EQ(bitDifferences(h, d), 0u);
                    continue;
                }
                const std::vector<float>& amplitude = host.channels[3].second;
                ASSERT_EQ(h.size(), d.size());
                size_t exact = 0;
                for (size_t i = 0; i < h.size(); ++i) {
                    EXPECT_LE(std::fabs(h[i] - d[i]), 1e-5f * std::max(1.0f, std::fabs(amplitude[i]))) << i;
                    exact += h[i] == d[i];
                }
                RecordProperty("displacement_exact_cells", int(exact));
                std::printf("displacement: %zu of %zu cells exact\n", exact, h.size());
            }
            // The density follows the displacement: within half its tolerance, and the same where saturated.
            ASSERT_EQ(host.density.size(), device.density.size());
            for (size_t i = 0; i < host.density.size(); ++i)
                EXPECT_LE(std::fabs(host.density[i] - device.density[i]), 1e-4f) << i;
            EXPECT_EQ(host.solves.size(), device.solves.size());
        }
    }
    expectNoValidationMessages();
}

} // namespace
} // namespace voxc

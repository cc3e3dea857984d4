// The spec's worked single step (B4.1): a 2x1 closed grid, b = (1, 0), d1 = (0.5, 0).
// Expected values are the spec's closed forms in double; float32 results within 1e-6.
#include "voxc/generators/terrain/Erosion.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace voxc::terrain {
namespace {

constexpr double kTolerance = 1e-6;

ErosionParams workedParams(Transport transport) {
    ErosionParams p;
    p.pipeArea = 1.0f;
    p.gravity = 4.0f;
    p.pipeLength = 1.0f;
    p.cellSize = 1.0f;
    p.dt = 0.1f;
    p.capacity = 1.0f;
    p.suspension = 0.5f;
    p.deposition = 0.5f;
    p.evaporation = 0.1f;
    p.depthLimit = std::numeric_limits<float>::infinity();
    p.rain = RainMode::None; // the rain hook: d1 is set directly
    p.transport = transport;
    return p;
}

ErosionGrid workedGrid() {
    ErosionGrid grid(2, 1);
    grid.base.values = {1.0f, 0.0f};
    grid.water.values = {0.5f, 0.0f};
    return grid;
}

// Closed forms of the worked step (spec B4.1).
const double kU0 = 0.3 / 0.47;                    // u(0) = dW_X / d_mean
const double kSuspended = 0.1 * 0.5 * std::sqrt(0.5) * kU0; // dt * K_s * C(0), C(0) = sin(phi) * |u|

TEST(ErosionStepTest, FluxWaterAndVelocityOfTheWorkedStep) {
    const ErosionParams params = workedParams(Transport::Conservative);
    ErosionGrid grid = workedGrid();
    updateFlux(grid, params);
    EXPECT_NEAR(grid.fluxR.values[0], 0.6, kTolerance);
    for (const Field2* flux : {&grid.fluxL, &grid.fluxT, &grid.fluxB}) EXPECT_EQ(flux->values[0], 0.0f);
    for (const Field2* flux : {&grid.fluxL, &grid.fluxR, &grid.fluxT, &grid.fluxB}) EXPECT_EQ(flux->values[1], 0.0f);
    updateWaterAndVelocity(grid, params);
    EXPECT_NEAR(grid.water.values[0], 0.44, kTolerance);
    EXPECT_NEAR(grid.water.values[1], 0.06, kTolerance);
    EXPECT_NEAR(grid.velocityU.values[0], kU0, kTolerance);
    EXPECT_NEAR(grid.velocityU.values[0], 0.638298, kTolerance); // the spec's printed value
    EXPECT_EQ(grid.velocityU.values[1], 5.0f); // 0.3 / 0.03 = 10, clamped to 0.5 * l_x / dt
    EXPECT_EQ(grid.velocityV.values[0], 0.0f);
}

TEST(ErosionStepTest, ErosionOfTheWorkedStep) {
    const ErosionParams params = workedParams(Transport::Conservative);
    ErosionGrid grid = workedGrid();
    updateFlux(grid, params);
    updateWaterAndVelocity(grid, params);
    erodeAndDeposit(grid, params);
    EXPECT_NEAR(grid.base.values[0] + grid.difference.values[0], 1.0 - kSuspended, kTolerance);
    EXPECT_NEAR(grid.base.values[0] + grid.difference.values[0], 0.977433, kTolerance);
    EXPECT_EQ(grid.difference.values[1], 0.0f);
    EXPECT_NEAR(grid.suspended.values[0], 0.022567, kTolerance);
    EXPECT_EQ(grid.suspended.values[1], 0.0f);
}

TEST(ErosionStepTest, WholeStepWithMeiTransport) {
    ErosionGrid grid = workedGrid();
    erosionStep(grid, workedParams(Transport::Mei), 0, 0);
    EXPECT_NEAR(grid.sediment.values[0], kSuspended, kTolerance);
    EXPECT_NEAR(grid.sediment.values[1], 0.5 * kSuspended, kTolerance); // sampled half way back
    EXPECT_NEAR(grid.sediment.values[1], 0.011284, kTolerance);
    EXPECT_NEAR(grid.water.values[0], 0.4356, kTolerance);
    EXPECT_NEAR(grid.water.values[1], 0.0594, kTolerance);
    // The backward sample creates sediment: sum(b + s) = 1.011284.
    const double solid = grid.base.values[0] + grid.difference.values[0] + grid.base.values[1] + grid.difference.values[1] +
                         grid.sediment.values[0] + grid.sediment.values[1];
    EXPECT_NEAR(solid, 1.0 + 0.5 * kSuspended, kTolerance);
}

TEST(ErosionStepTest, WholeStepWithConservativeTransport) {
    ErosionGrid grid = workedGrid();
    erosionStep(grid, workedParams(Transport::Conservative), 0, 0);
    const double moved = 0.1 * kU0; // u(0) dt / l_x of a cell
    EXPECT_NEAR(grid.sediment.values[0], kSuspended * (1.0 - moved), kTolerance);
    EXPECT_NEAR(grid.sediment.values[0], 0.021127, kTolerance);
    EXPECT_NEAR(grid.sediment.values[1], kSuspended * moved, kTolerance);
    EXPECT_NEAR(grid.sediment.values[1], 0.001440, kTolerance);
    EXPECT_NEAR(grid.water.values[0], 0.4356, kTolerance);
    EXPECT_NEAR(grid.water.values[1], 0.0594, kTolerance);
    const double solid = grid.base.values[0] + grid.difference.values[0] + grid.base.values[1] + grid.difference.values[1] +
                         grid.sediment.values[0] + grid.sediment.values[1];
    EXPECT_NEAR(solid, 1.0, kTolerance);
}

// The gather of B3.4 step 5 as a GPU kernel will run it: cell (x, y) sums s1 * (w_x * w_y) over its
// 3x3 sources in row-major order, w = 1 - frac at floor(arrival), frac one further, zero weights skipped.
float gatheredSediment(const ErosionGrid& g, const ErosionParams& p, int32_t x, int32_t y) {
    const int32_t w = g.width(), h = g.height();
    auto weight = [](float arrival, int32_t cell) {
        const float base = std::floor(arrival), frac = arrival - base;
        return float(cell) == base ? 1.0f - frac : (float(cell) == base + 1.0f ? frac : 0.0f);
    };
    float sum = 0.0f;
    for (int32_t sy = y - 1; sy <= y + 1; ++sy)
        for (int32_t sx = x - 1; sx <= x + 1; ++sx) {
            if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
            const size_t j = g.water.index(sx, sy);
            const float tx = std::clamp(float(sx) + (g.velocityU.values[j] * p.dt) / p.cellSize, 0.0f, float(w - 1));
            const float ty = std::clamp(float(sy) + (g.velocityV.values[j] * p.dt) / p.cellSize, 0.0f, float(h - 1));
            const float wx = weight(tx, x), wy = weight(ty, y);
            if (wx != 0.0f && wy != 0.0f) sum = sum + g.suspended.values[j] * (wx * wy);
        }
    return sum;
}

TEST(ErosionStepTest, ConservativeTransportIsTheDocumentedGatherBitForBit) {
    ErosionParams params;
    params.dt = 0.25f;
    params.cellSize = 1.0f;
    ErosionGrid grid(23, 17);
    const float limit = 0.5f * params.cellSize / params.dt;
    for (size_t i = 0; i < grid.suspended.values.size(); ++i) { // deterministic pseudo-random fields, with zeros and clamped speeds
        const float a = std::sin(float(i) * 12.9898f) * 43758.5453f, b = std::sin(float(i) * 78.233f) * 12345.678f;
        const float ua = a - std::floor(a), ub = b - std::floor(b);
        grid.suspended.values[i] = i % 7 == 0 ? 0.0f : ua * 0.01f;
        grid.velocityU.values[i] = i % 5 == 0 ? limit : (ua * 2.0f - 1.0f) * limit;
        grid.velocityV.values[i] = i % 11 == 0 ? -limit : (ub * 2.0f - 1.0f) * limit;
    }
    transportSediment(grid, params);
    for (int32_t y = 0; y < grid.height(); ++y)
        for (int32_t x = 0; x < grid.width(); ++x) ASSERT_EQ(grid.sediment.at(x, y), gatheredSediment(grid, params, x, y)) << x << "," << y;
}

TEST(ErosionStepTest, DropsAreDeterministicAndWithinTheirRanges) {
    ErosionParams params;
    params.seed = 7;
    for (uint32_t step = 0; step < 100; ++step) {
        const Drop drop = dropAt(params, 64, 32, 8, step);
        EXPECT_GE(drop.intensity, params.rainMin);
        EXPECT_LE(drop.intensity, params.rainMax);
        EXPECT_GE(drop.radius, params.radiusMin);
        EXPECT_LE(drop.radius, params.radiusMax);
        EXPECT_GE(drop.centreX, 0.0f);
        EXPECT_LT(drop.centreX, 64.0f);
        EXPECT_GE(drop.centreY, 0.0f);
        EXPECT_LT(drop.centreY, 32.0f);
        const Drop again = dropAt(params, 64, 32, 8, step);
        EXPECT_EQ(drop.centreX, again.centreX);
        EXPECT_EQ(drop.intensity, again.intensity);
    }
    EXPECT_NE(dropAt(params, 64, 32, 8, 0).centreX, dropAt(params, 64, 32, 9, 0).centreX); // the level keys the hash
}

// erosionSteps fuses the passes (rain with the surface, evaporation and the bed into the water
// pass) and splits a grid of 256 rows or more between two threads; every channel must still be
// the bits of the six passes run one after the other over the whole grid.
TEST(ErosionStepTest, FusedTwoThreadStepsEqualThePassesInOrder) {
    for (const Transport transport : {Transport::Conservative, Transport::Mei}) {
        ErosionParams params = findPreset("mountain_river")->params;
        params.transport = transport;
        params.seed = 3;
        ErosionGrid fused(300, 263); // odd height: the bands differ in size
        for (int32_t y = 0; y < fused.height(); ++y)
            for (int32_t x = 0; x < fused.width(); ++x) {
                fused.base.at(x, y) = float(0.5 + 0.3 * std::sin(x * 0.05) * std::cos(y * 0.07) + 0.02 * std::sin((x + y) * 0.9));
                fused.rain.at(x, y) = float(0.5 + 0.5 * std::cos(x * 0.02));
            }
        ErosionGrid passes = fused;
        erosionSteps(fused, params, 8, 0, 40, false);
        erosionSteps(fused, params, 8, 40, 5, true);
        for (uint32_t step = 0; step < 45; ++step) {
            const bool drain = step >= 40;
            if (!drain) addRain(passes, params, 8, step);
            updateFlux(passes, params);
            updateWaterAndVelocity(passes, params);
            erodeAndDeposit(passes, params);
            transportSediment(passes, params);
            evaporate(passes, drain ? 1.0f - 0.9f : 1.0f - params.evaporation * params.dt);
        }
        using G = ErosionGrid;
        for (const auto& [field, name] : {std::pair(&G::difference, "S_h"), {&G::water, "water"}, {&G::sediment, "sediment"},
                                          {&G::suspended, "suspended"}, {&G::fluxL, "flux L"}, {&G::fluxR, "flux R"},
                                          {&G::fluxT, "flux T"}, {&G::fluxB, "flux B"}, {&G::velocityU, "u"},
                                          {&G::velocityV, "v"}, {&G::surface, "surface"}}) {
            size_t differing = 0;
            for (size_t i = 0; i < (fused.*field).values.size(); ++i)
                differing += std::bit_cast<uint32_t>((fused.*field).values[i]) != std::bit_cast<uint32_t>((passes.*field).values[i]);
            EXPECT_EQ(differing, 0u) << name << (transport == Transport::Mei ? " (mei)" : "");
        }
        double moved = 0.0;
        for (float v : fused.difference.values) moved += std::fabs(v);
        EXPECT_GT(moved, 1e-2); // the steps did erode
    }
}

} // namespace
} // namespace voxc::terrain

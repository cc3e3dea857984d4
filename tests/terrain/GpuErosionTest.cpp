// The erosion steps on lavapipe against the host (spec B4.11): every channel bit for bit after
// 10 steps on 64² and odd-sized grids, for both transports, drops, uniform rain, no depth limit
// and the drain; and the whole terrain schedule with its steps on the device equal to the host's.
#include "Lavapipe.h"

#include "voxc/vulkan/GpuErosion.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace voxc {
namespace {

terrain::ErosionGrid hills(int32_t width, int32_t height) {
    terrain::ErosionGrid grid(width, height);
    for (int32_t y = 0; y < height; ++y)
        for (int32_t x = 0; x < width; ++x) {
            grid.base.at(x, y) = float(0.5 + 0.3 * std::sin(x * 0.21) * std::cos(y * 0.17) + 0.05 * std::sin((x + y) * 0.9));
            grid.rain.at(x, y) = float(0.5 + 0.5 * std::cos(x * 0.05));
            grid.capacity.at(x, y) = float(1.0 + 0.25 * std::sin(y * 0.3));
        }
    return grid;
}

// Differing values over all channels (bit patterns; the S_h ping-pong half included).
size_t differences(const terrain::ErosionGrid& a, const terrain::ErosionGrid& b) {
    size_t count = 0;
    const auto compare = [&](const terrain::Field2& x, const terrain::Field2& y, const char* name) {
        size_t differing = 0;
        for (size_t i = 0; i < x.values.size(); ++i)
            differing += std::bit_cast<uint32_t>(x.values[i]) != std::bit_cast<uint32_t>(y.values[i]);
        EXPECT_EQ(differing, 0u) << name;
        count += differing;
    };
    using G = terrain::ErosionGrid;
    for (const auto& [field, name] :
         {std::pair(&G::difference, "S_h"), {&G::differenceNext, "S_h (other half)"}, {&G::water, "water"},
          {&G::sediment, "sediment"}, {&G::suspended, "suspended"}, {&G::fluxL, "flux L"}, {&G::fluxR, "flux R"},
          {&G::fluxT, "flux T"}, {&G::fluxB, "flux B"}, {&G::velocityU, "u"}, {&G::velocityV, "v"},
          {&G::surface, "surface"}})
        compare(a.*field, b.*field, name);
    return count;
}

struct Case {
    const char* name;
    terrain::ErosionParams params;
    int32_t width, height;
    bool drain;
};

TEST(vulkan_GpuErosion, StepsMatchTheHostBitForBit) {
    const terrain::ErosionParams river = terrain::findPreset("mountain_river")->params;
    terrain::ErosionParams mei = river, uniform = river, unlimited = river, combined = terrain::findPreset("combined")->params;
    mei.transport = terrain::Transport::Mei;
    uniform.rain = terrain::RainMode::Uniform;
    uniform.uniformRain = 0.3f;
    unlimited.depthLimit = std::numeric_limits<float>::infinity();
    unlimited.minTilt = 0.05f;
    for (Case c : {Case{"mountain_river", river, 64, 64, false}, Case{"mei", mei, 64, 64, false},
                   Case{"uniform", uniform, 37, 23, false}, Case{"no depth limit", unlimited, 64, 64, false},
                   Case{"combined", combined, 50, 64, false}, Case{"drain", river, 64, 64, true}}) {
        SCOPED_TRACE(c.name);
        c.params.seed = 17;
        terrain::ErosionGrid host = hills(c.width, c.height);
        // Ten steps first, so the drain starts from moving water and the device from a used grid.
        terrain::runErosionSteps(host, c.params, 6, 0, 10, false);
        terrain::ErosionGrid device = host;
        terrain::runErosionSteps(host, c.params, 6, 10, 10, c.drain);
        vulkanErosionRunner(test::lavapipe())(device, c.params, 6, 10, 10, c.drain);
        EXPECT_EQ(differences(host, device), 0u);
        double moved = 0.0;
        for (float v : host.difference.values) moved += std::fabs(v);
        EXPECT_GT(moved, 1e-3); // the steps did erode
    }
}

TEST(vulkan_GpuErosion, ScheduleWithDeviceStepsMatchesTheHost) {
    terrain::TerrainMap map;
    map.domain.size = 64;
    map.domain.minLevel = 2;
    map.domain.maxLevel = 6;
    map.domain.maxHeight = 20;
    map.noise.amplitude = 2;
    terrain::Spline ridge;
    ridge.controlPoints = {{0, 16, 10}, {20, 18, 30}, {44, 12, 34}, {64, 15, 50}};
    terrain::MetaPoint meta;
    meta.radius = 3;
    meta.left = meta.right = {10, -8};
    meta.hardness = 0.2;
    ridge.metaPoints = {meta};
    ridge.minLevel = 2, ridge.maxLevel = 6;
    map.splines.push_back(ridge);
    terrain::ErosionSettings erosion = terrain::presetSettings("mountain_river");
    erosion.levelSteps = {{4, 30}, {5, 20}, {6, 15}};
    erosion.drainSteps = 10;
    const terrain::TerrainResult host = terrain::generateTerrain(map, erosion);
    erosion.runner = vulkanErosionRunner(test::lavapipe());
    const terrain::TerrainResult device = terrain::generateTerrain(map, erosion);
    for (const auto& [a, b] : {std::pair(&host.height, &device.height), std::pair(&host.difference, &device.difference),
                               std::pair(&host.water, &device.water), std::pair(&host.sediment, &device.sediment)})
        for (size_t i = 0; i < a->values.size(); ++i)
            ASSERT_EQ(std::bit_cast<uint32_t>(a->values[i]), std::bit_cast<uint32_t>(b->values[i])) << i;
    EXPECT_EQ(host.erosionCellSteps, device.erosionCellSteps);
}

} // namespace
} // namespace voxc

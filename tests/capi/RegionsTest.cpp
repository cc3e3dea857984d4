// An engine streaming regions through libvoxc: every Vulkan generation on a program runs on the
// program's one Vulkan context, so equal regions reuse the first one's pipelines, and each region
// still equals the interpreter's whole grid there, bit for bit.
#include <voxc/voxc.h>

#include <array>
#include <cstring>
#include <gtest/gtest.h>
#include <memory>

namespace {

struct ProgramFree {
    void operator()(voxc_program* program) const { voxc_program_free(program); }
};
struct GridFree {
    void operator()(voxc_grid* grid) const { voxc_grid_free(grid); }
};
using ProgramHandle = std::unique_ptr<voxc_program, ProgramFree>;
using GridHandle = std::unique_ptr<voxc_grid, GridFree>;

struct PipelineCounts {
    uint64_t created = 0;
    uint64_t shared = 0;
};

PipelineCounts pipelineCounts(const voxc_program* program) {
    PipelineCounts counts;
    voxc_program_pipeline_counts(program, &counts.created, &counts.shared);
    return counts;
}

ProgramHandle load(const char* example) {
    voxc_program* program = nullptr;
    const std::string path = std::string(VOXC_SOURCE_DIR) + "/examples/" + example + ".vox";
    EXPECT_EQ(voxc_program_load(path.c_str(), nullptr, &program), VOXC_OK) << voxc_last_error();
    return ProgramHandle(program);
}

GridHandle generate(const voxc_program* program, voxc_backend backend) {
    voxc_grid* grid = nullptr;
    EXPECT_EQ(voxc_generate(program, backend, &grid), VOXC_OK) << voxc_last_error();
    return GridHandle(grid);
}

GridHandle generateRegion(const voxc_program* program, std::array<int32_t, 3> min, std::array<int32_t, 3> max) {
    voxc_grid* grid = nullptr;
    EXPECT_EQ(voxc_generate_region(program, min.data(), max.data(), VOXC_BACKEND_VULKAN, &grid), VOXC_OK)
        << voxc_last_error();
    return GridHandle(grid);
}

// Voxels of `part` (a region's grid) whose density bits or material differ from `whole`'s voxel at
// the same world coordinate.
size_t differencesFromWhole(const voxc_grid* whole, const voxc_grid* part) {
    int32_t wholeSize[3], wholeOrigin[3], size[3], origin[3];
    voxc_grid_size(whole, wholeSize);
    voxc_grid_origin(whole, wholeOrigin);
    voxc_grid_size(part, size);
    voxc_grid_origin(part, origin);
    const float* wholeDensities = voxc_grid_densities(whole);
    const uint8_t* wholeMaterials = voxc_grid_materials(whole);
    const float* densities = voxc_grid_densities(part);
    const uint8_t* materials = voxc_grid_materials(part);
    size_t differences = 0;
    for (int32_t z = 0; z < size[2]; ++z)
        for (int32_t y = 0; y < size[1]; ++y)
            for (int32_t x = 0; x < size[0]; ++x) {
                const size_t i = size_t(x) + size_t(size[0]) * (size_t(y) + size_t(size[1]) * size_t(z));
                const size_t w = size_t(x + origin[0] - wholeOrigin[0]) +
                                 size_t(wholeSize[0]) * (size_t(y + origin[1] - wholeOrigin[1]) +
                                                         size_t(wholeSize[1]) * size_t(z + origin[2] - wholeOrigin[2]));
                differences += std::memcmp(&densities[i], &wholeDensities[w], sizeof(float)) != 0 ||
                               materials[i] != wholeMaterials[w];
            }
    return differences;
}

// scene.vox (96 x 64 x 96, a grammar whose halo is 14 voxels along y): boxes of 24^3 whose grown
// boxes stay inside the grid, so all have the same computed size and compile to the same kernels.
TEST(CApiRegions, EqualRegionsShareTheProgramsPipelinesAndEqualTheInterpreter) {
    const ProgramHandle program = load("scene");
    ASSERT_TRUE(program);
    EXPECT_EQ(pipelineCounts(program.get()).created, 0u) << "no context before the first Vulkan generation";
    const GridHandle whole = generate(program.get(), VOXC_BACKEND_INTERPRETER);
    ASSERT_TRUE(whole);
    EXPECT_EQ(pipelineCounts(program.get()).created, 0u) << "the interpreter needs no Vulkan context";

    int32_t size[3], origin[3];
    voxc_program_grid(program.get(), size, origin);
    const std::array<std::array<int32_t, 2>, 4> corners{{{0, 0}, {24, 0}, {48, 72}, {72, 24}}}; // x, z
    PipelineCounts first;
    for (size_t r = 0; r < corners.size(); ++r) {
        const std::array<int32_t, 3> min{origin[0] + corners[r][0], origin[1] + 20, origin[2] + corners[r][1]};
        const std::array<int32_t, 3> max{min[0] + 24, min[1] + 24, min[2] + 24};
        const GridHandle region = generateRegion(program.get(), min, max);
        ASSERT_TRUE(region);
        EXPECT_EQ(differencesFromWhole(whole.get(), region.get()), 0u) << "region " << r;

        const PipelineCounts counts = pipelineCounts(program.get());
        if (r == 0) {
            first = counts;
            EXPECT_GT(first.created, 0u);
            continue;
        }
        // Each later region takes every kernel from the first: the driver compiles nothing new.
        EXPECT_EQ(counts.created, first.created) << "region " << r;
        EXPECT_EQ(counts.shared, first.shared + r * (first.created + first.shared)) << "region " << r;
    }

    // The whole grid on the same context: its own kernels once, then shared by a second run.
    const GridHandle vulkanWhole = generate(program.get(), VOXC_BACKEND_VULKAN);
    ASSERT_TRUE(vulkanWhole);
    EXPECT_EQ(differencesFromWhole(whole.get(), vulkanWhole.get()), 0u);
    const PipelineCounts afterWhole = pipelineCounts(program.get());
    const GridHandle again = generate(program.get(), VOXC_BACKEND_VULKAN);
    ASSERT_TRUE(again);
    const PipelineCounts afterAgain = pipelineCounts(program.get());
    EXPECT_EQ(afterAgain.created, afterWhole.created);
    EXPECT_GT(afterAgain.shared, afterWhole.shared);
}

TEST(CApiRegions, PipelineCountsOfNoProgramAreZero) {
    uint64_t created = 7, shared = 7;
    voxc_program_pipeline_counts(nullptr, &created, &shared);
    EXPECT_EQ(created, 0u);
    EXPECT_EQ(shared, 0u);
    voxc_program_pipeline_counts(nullptr, nullptr, nullptr); // accepted, as the other accessors' nulls
}

} // namespace

// What one stage changed (voxc/interp/GridDiff.h): each voxel's kind of change, the counts by kind
// and material against a direct count, the box, and the slices that show materials and changes.
#include "voxc/interp/GridDiff.h"
#include "voxc/interp/Slice.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <random>

namespace voxc {
namespace grid_diff_test {

TEST(interp_GridDiff, KindsOfChange) {
    EXPECT_EQ(classifyChange(1.0f, 1, 0.0f, 1, 0.5f), ChangeKind::Carved);
    EXPECT_EQ(classifyChange(0.0f, 0, 0.9f, 2, 0.5f), ChangeKind::Filled);
    EXPECT_EQ(classifyChange(1.0f, 1, 1.0f, 2, 0.5f), ChangeKind::MaterialChanged);
    EXPECT_EQ(classifyChange(0.0f, 0, 0.2f, 3, 0.5f), ChangeKind::MaterialChanged); // in air, still a change
    EXPECT_EQ(classifyChange(1.0f, 1, 0.7f, 1, 0.5f), ChangeKind::DensityChanged);
    EXPECT_EQ(classifyChange(0.0f, 1, -0.0f, 1, 0.5f), ChangeKind::DensityChanged); // bits, not values
    EXPECT_EQ(classifyChange(0.5f, 1, 0.5f, 1, 0.5f), ChangeKind::None);
    EXPECT_EQ(classifyChange(0.5f, 1, 0.6f, 1, 0.5f), ChangeKind::Filled); // solid is above iso
}

TEST(interp_GridDiff, CountsMatchADirectComparison) {
    const glm::ivec3 size(9, 7, 5);
    DenseGrid before(size), after(size);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> pick(0, 3);
    const float densities[] = {0.0f, 0.3f, 0.8f, 1.0f};
    for (size_t i = 0; i < before.data().size(); ++i) {
        before.data()[i] = densities[pick(random)];
        before.materials()[i] = uint8_t(pick(random));
        const bool keep = pick(random) != 0;
        after.data()[i] = keep ? before.data()[i] : densities[pick(random)];
        after.materials()[i] = keep ? before.materials()[i] : uint8_t(pick(random));
    }
    const GridDiff diff = diffGrids(before, after, 0.5f);
    uint64_t expected[kChangeKinds] = {};
    uint64_t changed = 0;
    glm::ivec3 lo(size), hi(-1);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 p(x, y, z);
                const bool solidBefore = before.at(p) > 0.5f, solidAfter = after.at(p) > 0.5f;
                size_t kind = 0;
                if (solidBefore && !solidAfter) kind = 1;
                else if (!solidBefore && solidAfter) kind = 2;
                else if (before.materialAt(p) != after.materialAt(p)) kind = 3;
                else if (before.at(p) != after.at(p)) kind = 4;
                ++expected[kind];
                if (kind == 0) continue;
                ++changed;
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    EXPECT_EQ(diff.changed, changed);
    for (size_t kind = 1; kind < kChangeKinds; ++kind) {
        uint64_t total = 0;
        for (uint64_t count : diff.counts[kind]) total += count;
        EXPECT_EQ(total, expected[kind]) << changeKindName(ChangeKind(kind));
    }
    uint64_t pairs = 0;
    for (const auto& entry : diff.materialChanges) pairs += entry.second;
    EXPECT_EQ(pairs, expected[3]);
    EXPECT_EQ(diff.min, lo);
    EXPECT_EQ(diff.max, hi);
}

Program twoMaterials() {
    Program program;
    program.materials = {{"rock", {}, 1, {}}, {"roots", {}, 2, {}}, {"sand", {}, 3, {}}};
    return program;
}

TEST(interp_GridDiff, ReportAndSlices) {
    DenseGrid before(glm::ivec3(4, 1, 2)), after(glm::ivec3(4, 1, 2));
    for (int x = 0; x < 4; ++x) {
        before.at({x, 0, 0}) = 1.0f;
        before.materialAt({x, 0, 0}) = 1;
    }
    after = before;
    after.at({0, 0, 0}) = 0.0f;         // carved rock
    after.at({1, 0, 1}) = 1.0f;         // filled with sand
    after.materialAt({1, 0, 1}) = 3;
    after.materialAt({2, 0, 0}) = 2;    // rock -> roots
    after.at({3, 0, 0}) = 0.75f;        // denser or not, still solid rock
    const Program program = twoMaterials();
    const GridDiff diff = diffGrids(before, after, 0.5f);
    EXPECT_EQ(formatGridDiff(program, diff),
              "changed voxels: 4 (solid: density > 0.5)\n"
              "  carved:           1 (was rock 1)\n"
              "  filled:           1 (now sand 1)\n"
              "  material changed: 1 (rock -> roots 1)\n"
              "  density changed:  1 (now rock 1)\n"
              "  box of the change: (0,0,0)..(3,0,1) inclusive, grid voxels; 4x1x2\n");
    const std::string changes = renderDiffSlice(before, after, 0.5f, 1, 0);
    EXPECT_NE(changes.find("'-' carved  '+' filled  'm' material changed  '~' density changed"), std::string::npos);
    EXPECT_NE(changes.find("\n1 | +  |\n0 |-#m~|\n"), std::string::npos) << changes;
    const std::string materials = renderMaterialSlice(program, after, 0.5f, 1, 0);
    EXPECT_NE(materials.find("'.' none  'r' rock  'R' roots  's' sand"), std::string::npos) << materials;
    EXPECT_NE(materials.find("\n1 | s  |\n0 | rRr|\n"), std::string::npos) << materials;
}

} // namespace grid_diff_test
} // namespace voxc

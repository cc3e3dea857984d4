#pragma once
// What one pipeline stage changed: two grids of one size compared voxel by voxel, each change
// sorted into a kind, for `voxc interp --diff` and `voxc run --diff`.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <map>
#include <string>
#include <utility>

namespace voxc {

// A voxel is solid when its density is above `iso` (the mesh's surface level).
enum class ChangeKind : uint8_t {
    None,            // the same density bits and material
    Carved,          // solid before, not after
    Filled,          // not solid before, solid after
    MaterialChanged, // the material differs; solid before and after, or not solid before and after
    DensityChanged,  // only the density differs, on the same side of iso
};
constexpr size_t kChangeKinds = 5;

// "carved", "filled", "material changed", "density changed" ("unchanged" for None).
const char* changeKindName(ChangeKind kind);

ChangeKind classifyChange(float densityBefore, uint8_t materialBefore, float densityAfter, uint8_t materialAfter,
                          float iso);

struct GridDiff {
    float iso = 0.5f;
    uint64_t changed = 0;
    // Per kind, per material id: carved voxels count under their material before, the other kinds
    // under their material after.
    std::array<std::array<uint64_t, 256>, kChangeKinds> counts{};
    // Material changes by (before, after) id.
    std::map<std::pair<uint8_t, uint8_t>, uint64_t> materialChanges;
    // The changed voxels' box, inclusive, grid-local; meaningful when changed > 0.
    glm::ivec3 min{0}, max{0};
    // The y layer with the most changes (the lowest of equals); meaningful when changed > 0.
    int busiestY = 0;
};

// `before` and `after` must have the same size.
GridDiff diffGrids(const DenseGrid& before, const DenseGrid& after, float iso);

// The report: the total, a line per kind with its count by material (names from `program`),
// the material changes as "rock -> moss 40", and the box of the change.
std::string formatGridDiff(const Program& program, const GridDiff& diff);

// One layer (as renderSlice lays it out) marking each voxel's change: ' ' unchanged and not
// solid, '#' unchanged and solid, '-' carved, '+' filled, 'm' material changed, '~' density changed.
std::string renderDiffSlice(const DenseGrid& before, const DenseGrid& after, float iso, int axis, int index);

} // namespace voxc

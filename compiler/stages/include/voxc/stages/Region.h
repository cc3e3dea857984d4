#pragma once
// Regions: any box of the declared world computed on its own, bit for bit as the whole grid
// computes it there. The box is grown by the pipeline's halo (the sum of its stages' dependency
// radii, StageKind::dependencyRadius), clipped to the declared grid, run as a grid of its own at
// its place in the world, and cropped.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"
#include "voxc/stages/StageKind.h"

#include <string>
#include <utility>
#include <vector>

namespace voxc::stages {

// Half-open boxes of the declared grid in the file's grid-local voxels: min <= p < max.
struct GridBox {
    glm::ivec3 min{0}, max{0};
    glm::ivec3 size() const { return max - min; }
};

struct PipelineHalo {
    glm::ivec3 radius{0};             // the sum over the stages, capped at world size - 1
    std::vector<StageRadius> stages;  // per stage of program.pipeline, in order
};

// A voxel after the pipeline depends on voxels before it at most this far away per axis.
PipelineHalo pipelineHalo(const Program& program);

// `region` grown by `halo` and clipped to the declared grid.
GridBox haloBox(const Program& program, const GridBox& region, glm::ivec3 halo);

// The program whose grid is `box` of `program`'s (a whole-world program, localBase 0): the same
// world position, seed and chunking, with World::localBase, grammar bounds and anchor numbering
// (Grammar::firstAnchor) and solve blocks (their boxes, and their tables once solved) moved into
// the box, so every stage computes what it computes there in the declared grid, up to the box's
// border effects the halo keeps out.
Program regionProgram(const Program& program, const GridBox& box);

// The cells of `table` inside `box`, moved to its grid-local voxels (possibly none); the solve's
// channels are left out.
std::shared_ptr<const SolveTable> regionTable(const SolveTable& table, const GridBox& box);

// The voxels of `box` (grid-local to `grid`), both channels.
DenseGrid cropGrid(const DenseGrid& grid, const GridBox& box);

// Parses "MINX,MINY,MINZ:MAXX,MAXY,MAXZ" (world coordinates, half-open): its min and max corners;
// UserError unless it is a non-empty box.
std::pair<glm::ivec3, glm::ivec3> parseWorldBox(const std::string& text);
// That box in the file's grid-local voxels; UserError unless it lies inside the declared grid.
GridBox parseRegion(const std::string& text, const World& world);

} // namespace voxc::stages

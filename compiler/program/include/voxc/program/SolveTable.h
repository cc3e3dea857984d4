#pragma once
// The result of a global solve (a `curves` or `terrain` block, docs/curves.md): a density, and
// optionally a material id, per voxel of a box of the grid, computed once per run
// (stages::solveBlocks), never by the check. The interpreter combines it with the grid directly; generated
// kernels read the same values through kBindingSolveTables (solveTableWords), so both backends
// combine the same floats.
#include "voxc/core/SourceLoc.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace voxc {

namespace curves {
struct Scene; // voxc/generators/curves/Scene.h
}
namespace terrain {
struct TerrainBlock; // voxc/generators/terrain/Block.h
}

// A multigrid level's cells per axis and its max residual (in finest-cell units, docs/curves.md)
// at the end of its full-multigrid stage.
struct LevelResidual {
    glm::ivec3 size{0};
    float residual = 0.0f;
};

// One iterative solve as `voxc run` reports it.
struct SolveSummary {
    std::string name;              // e.g. "normals", "parameters"
    int32_t levels = 0;            // multigrid levels
    // Max residual after the full-multigrid start (index 0) and after each V-cycle.
    std::vector<float> residuals;
    // Per level, coarsest first, the last (the finest) being residuals[0]; empty when the
    // multigrid ran on a device, which keeps only the finest level's residuals.
    std::vector<LevelResidual> fullMultigrid;

    int32_t cycles() const { return int32_t(residuals.size()) - 1; }
};

// A terrain block's final maps on its finest level, row-major, side x side cells, heights in units
// of max_height (what `voxc terrain` writes out).
struct TerrainMaps {
    int32_t side = 0;
    std::vector<float> height, water, sediment;
    std::vector<float> difference; // S_h: the eroded height minus the uneroded one
};

struct SolveTable {
    glm::ivec3 min{0};  // grid-local voxel of cell (0,0,0)
    glm::ivec3 size{0}; // cells per axis, each >= 1
    // x fastest, then y, then z; densities in [0, 1], but heights in world voxels for a map that
    // fields sample (source "map", size (side, 1, side): codegen::mapTable).
    std::vector<float> density;
    std::vector<uint8_t> material;  // same order; empty when the solve writes no material
    std::vector<SolveSummary> solves;
    std::string source = "curves"; // the block kind that made it: "curves", "terrain" or "map"
    std::string notes;             // what the solve did besides `solves`, for reports (may be empty)
    std::shared_ptr<const TerrainMaps> terrainMaps; // terrain blocks only
    // The solve's intermediate channels by name (curves: docs/curves.md "Dumping channels"), each
    // in `density`'s order, kept only when the run asks (stages::SolveOptions::keepChannels).
    std::vector<std::pair<std::string, std::vector<float>>> channels;
    // Wall time of the solve's parts in order (curves: voxelize unless the check did, normals,
    // parameters, material, surface, smoothing, density), for benchmarks; never printed, nothing
    // depends on it.
    std::vector<std::pair<std::string, double>> phaseMs;

    uint64_t cellCount() const { return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z); }
};

// A declared `curves` or `terrain` block. The check knows its box and whether it writes materials;
// its table is made only by a run (stages::solveBlocks, from `scene` or `terrain`), so checking a
// file never runs a solve.
struct CurvesBlock {
    std::string name;
    SourceLoc loc;
    std::string source = "curves"; // SolveTable::source
    glm::ivec3 min{0}, size{0};    // the table's box, grid-local
    bool writesMaterials = false;  // the table has a material channel
    std::vector<uint8_t> materials; // the ids it may write, ascending (W0208: which materials are used)
    std::shared_ptr<const curves::Scene> scene; // curves blocks: the checked, voxelised scene
    std::shared_ptr<const SolveTable> table;    // null until solved (stages::solveBlocks)
    std::shared_ptr<const terrain::TerrainBlock> terrain; // terrain blocks: the checked block

    // The table; InternalError when no run solved the block.
    const SolveTable& solved() const;
    uint64_t cellCount() const { return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z); }
};

// The words of kBindingSolveTables: word 0 the table count n, words 1..n each table's first
// word; a table is min (3 ints), size (3 ints), then its densities (float bits), then its
// materials (one word each, only when it has materials).
std::vector<int32_t> solveTableWords(const std::vector<std::shared_ptr<const SolveTable>>& tables);
// How many words solveTableWords makes, and the same words written into `out` (that many): an
// executor fills its mapped buffer directly (a 256x128x256 table with materials is 64 MiB).
size_t solveTableWordCount(const std::vector<std::shared_ptr<const SolveTable>>& tables);
void writeSolveTableWords(const std::vector<std::shared_ptr<const SolveTable>>& tables, std::span<int32_t> out);

} // namespace voxc

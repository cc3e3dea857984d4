// A curves stage: the table of a curves or terrain block (SolveTable, solved once per run by
// stages::solveBlocks, a terrain block's when the file is checked) combined with the grid inside the
// block's box by the stage's mode, with the table's materials where it wins. One kernel per (block,
// mode), dispatched over the box only, split at chunk borders so boxes whose combine provably
// changes nothing are skipped. Only the plan and the interpretation read the table; the check's
// questions (work, materials, radius) are answered from the block's box.
#include "Kinds.h"

#include "voxc/codegen/CurvesKernel.h"

#include <algorithm>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

namespace voxc::stages {

namespace {

const CurvesBlock& blockOf(const Program& program, const Stage& stage) { return program.curves.at(stage.index); }

std::string label(const Program& program, const Stage& stage) {
    return fmt::format("{} {}", ir::fieldModeName(stage.mode), program.curves.at(stage.index).name);
}

// Even a set leaves the voxels outside its box as they were, so the stages before it stay live.
bool readsDensities(const Stage&) { return true; }

bool writesMaterials(const Program& program, const Stage& stage) { return blockOf(program, stage).writesMaterials; }

StageWork estimateWork(const Program& program, const Stage& stage, double) {
    const double cells = double(blockOf(program, stage).cellCount());
    return {cells, stage.loc,
            fmt::format("curves '{}' ({} cells combined)", program.curves.at(stage.index).name, formatWork(cells))};
}

std::string kernelName(const Program& program, const Stage& stage) {
    return fmt::format("{}_{}", program.curves.at(stage.index).name, ir::fieldModeName(stage.mode));
}

int64_t newKernels(const Program& program, const Stage& stage, std::set<std::string>& seen) {
    return seen.insert(kernelName(program, stage)).second ? 1 : 0;
}

// The table is solved over the block's whole declared box, whatever grid runs, so the stage
// samples it by position and combines it with the voxel's own density.
StageRadius dependencyRadius(const Program& program, const Stage& stage) {
    return {glm::ivec3(0), fmt::format("a table solved once over the {} block's box, sampled by position",
                                       blockOf(program, stage).source)};
}

// The checker keeps the box inside the grid, and every table value is a finite float in [0, 1].
void interpret(const Program& program, const Stage& stage, DenseGrid& grid, const InterpOptions&, NonFiniteCount*) {
    const SolveTable& table = blockOf(program, stage).solved();
    const bool materials = !table.material.empty();
    size_t at = 0;
    for (int32_t z = 0; z < table.size.z; ++z)
        for (int32_t y = 0; y < table.size.y; ++y)
            for (int32_t x = 0; x < table.size.x; ++x, ++at) {
                const glm::ivec3 p = table.min + glm::ivec3(x, y, z);
                const VoxelState voxel{grid.at(p), grid.materialAt(p)};
                const VoxelState out = materials ? combineField(stage.mode, table.material[at], table.density[at], voxel)
                                                 : combineField(stage.mode, std::nullopt, table.density[at], voxel);
                grid.at(p) = out.density;
                grid.materialAt(p) = out.material;
            }
}

// Kernels in (block, mode) order; tables in block order, each uploaded once.
void addKernels(PlanContext& context) {
    std::map<std::pair<uint32_t, FieldMode>, Stage> kinds;
    for (const Stage& stage : context.module.pipeline)
        if (stage.kind == Stage::Kind::Curves) kinds.emplace(std::pair(stage.index, stage.mode), stage);
    std::map<uint32_t, uint32_t> tableIndex;
    for (const auto& [key, stage] : kinds) {
        const CurvesBlock& block = context.program.curves.at(key.first);
        auto [it, inserted] = tableIndex.emplace(key.first, uint32_t(context.package.solveTables.size()));
        const SolveTable& table = block.solved(); // before a null table could reach the package
        if (inserted) context.package.solveTables.push_back(block.table);
        const std::string name = kernelName(context.program, stage);
        const std::string origin = fmt::format("{}:{}:{} curves {}, {}", context.sourceName, block.loc.line,
                                               block.loc.column, block.name, ir::fieldModeName(key.second));
        context.kernels[name] = context.addKernel(
            name, origin, codegen::curvesDispatchShape(context.module),
            codegen::curvesKernelSource(context.module, it->second, key.second, !table.material.empty(), name,
                                        origin));
    }
}

// The table's value range over cells [lo, hi) of the box (box-local).
codegen::DensityBounds tableRange(const SolveTable& table, glm::ivec3 lo, glm::ivec3 hi) {
    codegen::DensityBounds range{1.0f, 0.0f};
    for (int32_t z = lo.z; z < hi.z; ++z)
        for (int32_t y = lo.y; y < hi.y; ++y)
            for (int32_t x = lo.x; x < hi.x; ++x) {
                const float f = table.density[size_t(x) + size_t(table.size.x) * (size_t(y) + size_t(table.size.y) * size_t(z))];
                range.lo = std::min(range.lo, f), range.hi = std::max(range.hi, f);
            }
    return range;
}

// combineField leaves every voxel (density and material) as it is: nothing wins, for every
// density d in `before` and every value f in `range`.
bool combineKeepsGrid(FieldMode mode, codegen::DensityBounds range, std::optional<codegen::DensityBounds> before) {
    if (!before) return false;
    switch (mode) {
    case FieldMode::Union: return range.hi <= before->lo;            // d < f never
    case FieldMode::Subtract: return 1.0f - range.hi >= before->hi;  // 1 - f < d never
    case FieldMode::Intersect: return range.lo >= before->hi;        // f < d never
    case FieldMode::Set:
    case FieldMode::Paint: return false;
    }
    return false;
}

// Boxes tiling the grid: the solve box split at the world-aligned chunk borders (each piece
// skipped where its combine provably changes nothing), and the slabs around it, skipped.
void plan(PlanContext& context, const Stage& stage, StagePlan& plan) {
    const SolveTable& table = blockOf(context.program, stage).solved();
    plan.gridKernel = context.kernels.at(kernelName(context.program, stage));
    plan.attributes.emplace_back("curves", context.program.curves.at(stage.index).name);
    plan.attributes.emplace_back("mode", std::string(ir::fieldModeName(stage.mode)));
    const World& world = context.module.world;
    const glm::ivec3 lo = table.min, hi = table.min + table.size;
    // Outside the box: the slabs below/above in z, then y, then x, none dispatched.
    const auto skipped = [&](glm::ivec3 a, glm::ivec3 b) {
        if (glm::all(glm::lessThan(a, b))) plan.gridBoxes.push_back({a, b, true, 0.0f, true});
    };
    skipped({0, 0, 0}, {world.size.x, world.size.y, lo.z});
    skipped({0, 0, hi.z}, world.size);
    skipped({0, 0, lo.z}, {world.size.x, lo.y, hi.z});
    skipped({0, hi.y, lo.z}, {world.size.x, world.size.y, hi.z});
    skipped({0, lo.y, lo.z}, {lo.x, hi.y, hi.z});
    skipped({hi.x, lo.y, lo.z}, {world.size.x, hi.y, hi.z});
    // Inside: pieces cut at chunk borders (world coordinates multiple of the chunk size).
    const int32_t c = world.chunkSize;
    const auto nextBorder = [&](int32_t local, int axis) {
        const int32_t w = world.origin[axis] + local;
        const int32_t floorChunk = (w >= 0 ? w / c : -((-w + c - 1) / c)) * c;
        return floorChunk + c - world.origin[axis];
    };
    const std::optional<codegen::DensityBounds> before = context.densities;
    codegen::DensityBounds whole = tableRange(table, glm::ivec3(0), table.size);
    for (int32_t z = lo.z; z < hi.z; z = std::min(nextBorder(z, 2), hi.z))
        for (int32_t y = lo.y; y < hi.y; y = std::min(nextBorder(y, 1), hi.y))
            for (int32_t x = lo.x; x < hi.x; x = std::min(nextBorder(x, 0), hi.x)) {
                const glm::ivec3 a{x, y, z};
                const glm::ivec3 b = glm::min(glm::ivec3(nextBorder(x, 0), nextBorder(y, 1), nextBorder(z, 2)), hi);
                const bool keeps = combineKeepsGrid(stage.mode, tableRange(table, a - lo, b - lo), before);
                plan.gridBoxes.push_back({a, b, keeps, 0.0f, keeps});
            }
    // Densities after: the grid's and the combined values (1 - f for subtract).
    if (before) {
        const codegen::DensityBounds combined =
            stage.mode == FieldMode::Subtract ? codegen::DensityBounds{1.0f - whole.hi, 1.0f - whole.lo} : whole;
        const bool boxIsGrid = lo == glm::ivec3(0) && hi == world.size;
        if (stage.mode == FieldMode::Set && boxIsGrid)
            context.densities = combined;
        else
            context.densities = codegen::DensityBounds{std::min(before->lo, combined.lo), std::max(before->hi, combined.hi)};
    }
}

} // namespace

const StageKind kCurvesStage{Stage::Kind::Curves, "curves", label,     readsDensities, writesMaterials, estimateWork,
                             newKernels,          dependencyRadius, interpret, addKernels, plan};

} // namespace voxc::stages

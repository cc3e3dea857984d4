#include "voxc/generators/terrain/Block.h"

#include "voxc/program/Program.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace voxc::terrain {

namespace {

// A map of the finest level at world (wx, wz): bilinear between its cell centres, clamped at the edges.
double sample(const Field2& map, const Domain& domain, double wx, double wz) {
    const double cell = domain.cellSize(domain.maxLevel);
    const double u = (wx - domain.origin.x) / cell - 0.5, v = (wz - domain.origin.y) / cell - 0.5;
    const double fu = std::floor(std::clamp(u, -1.0, double(map.width))), fv = std::floor(std::clamp(v, -1.0, double(map.height)));
    const int32_t i = int32_t(fu), j = int32_t(fv);
    const double tu = std::clamp(u - fu, 0.0, 1.0), tv = std::clamp(v - fv, 0.0, 1.0);
    const double top = map.clamped(i, j) * (1 - tu) + map.clamped(i + 1, j) * tu;
    const double bottom = map.clamped(i, j + 1) * (1 - tu) + map.clamped(i + 1, j + 1) * tu;
    return top * (1 - tv) + bottom * tv;
}

// The height map as densities over the whole checked world: (H - y) / ramp + 0.5 clamped to
// [0, 1], so the 0.5 surface lies at the height; materials where solid (the deposit material where
// erosion raised the ground by more than the threshold).
SolveTable voxelise(const TerrainBlock& block, const TerrainResult& result) {
    const glm::ivec3 origin = block.worldOrigin, size = block.worldSize;
    SolveTable table;
    table.min = glm::ivec3(0);
    table.size = size;
    table.density.resize(size_t(table.cellCount()));
    const bool materials = block.material || block.depositMaterial;
    if (materials) table.material.resize(table.density.size(), kMaterialNone);
    const Domain& domain = block.map.domain;
    size_t at = 0;
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x, ++at) {
                const double wx = origin.x + x, wy = origin.y + y, wz = origin.z + z;
                const double height = block.base + sample(result.height, domain, wx, wz) * domain.maxHeight;
                const float density = float(std::clamp((height - wy) / block.ramp + 0.5, 0.0, 1.0));
                table.density[at] = density;
                if (!materials || density < 0.5f) continue;
                const double raised = sample(result.difference, domain, wx, wz) * domain.maxHeight;
                if (block.depositMaterial && raised > block.depositThreshold)
                    table.material[at] = *block.depositMaterial;
                else if (block.material)
                    table.material[at] = *block.material;
            }
    table.source = "terrain";
    table.terrainMaps = std::make_shared<const TerrainMaps>(
        TerrainMaps{result.height.width, result.height.values, result.water.values, result.sediment.values, result.difference.values});
    table.notes = fmt::format("levels {}..{} ({}^2 cells), {} erosion steps ({} cell-steps), water {:.4g}, sediment "
                              "{:.4g}, ground moved {:.4g} (sums over the finest level, in units of max_height)",
                              domain.minLevel, domain.maxLevel, result.height.width, result.erosionSteps,
                              result.erosionCellSteps, result.totalWater, result.totalSediment,
                              result.totalDifference);
    return table;
}

} // namespace

std::shared_ptr<const SampledMap> declaredMap(const TerrainBlock& block) {
    const Domain& domain = block.map.domain;
    auto map = std::make_shared<SampledMap>();
    map->name = block.name;
    map->source = "terrain";
    const int32_t side = int32_t(1) << domain.maxLevel;
    map->size = {side, 1, side};
    map->origin = {float(domain.origin.x), 0.0f, float(domain.origin.y)};
    const float cellsPerVoxel = float(1.0 / domain.cellSize(domain.maxLevel));
    map->cellsPerVoxel = {cellsPerVoxel, 1.0f, cellsPerVoxel};
    return map;
}

std::shared_ptr<const SampledMap> solvedMap(const TerrainBlock& block, const TerrainMaps& maps) {
    const Domain& domain = block.map.domain;
    auto map = std::make_shared<SampledMap>(*declaredMap(block));
    map->size = {maps.side, 1, maps.side};
    map->values.reserve(maps.height.size());
    for (float h : maps.height) map->values.push_back(float(block.base + double(h) * domain.maxHeight));
    const auto [lowest, highest] = std::minmax_element(map->values.begin(), map->values.end());
    map->lowest = *lowest, map->highest = *highest;
    return map;
}

SolvedTerrain solveTerrain(const TerrainBlock& block, const ErosionRunner& runner) {
    std::optional<ErosionSettings> erosion = block.erosion;
    if (erosion) erosion->runner = runner;
    SolvedTerrain solved{voxelise(block, generateTerrain(block.map, erosion, block.limits)), nullptr};
    solved.map = solvedMap(block, *solved.table.terrainMaps);
    return solved;
}

} // namespace voxc::terrain

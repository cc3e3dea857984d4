#pragma once
// A checked `terrain` block (docs/terrain.md, "In a .vox file"): everything its solve needs,
// read and validated by the check and kept on the program (CurvesBlock::terrain), so checking a
// file never generates a map. A run solves it once (stages::solveBlocks): the generator's maps,
// voxelised into a SolveTable over the checked world, and the height map fields sample.
#include "voxc/generators/terrain/Terrain.h"
#include "voxc/program/SampledMap.h"
#include "voxc/program/SolveTable.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>

namespace voxc::terrain {

struct TerrainBlock {
    std::string name;
    TerrainMap map;
    std::optional<ErosionSettings> erosion; // its runner empty: the solve is told where steps run
    double base = 0.0, ramp = 2.0;          // world y of height 0; density ramp in voxels
    std::optional<uint8_t> material, depositMaterial;
    double depositThreshold = 0.5;
    glm::ivec3 worldOrigin{0}, worldSize{0}; // the checked world, which the table covers whole
    Limits limits;
};

// The map a field samples before the block is solved: its name and placement, no heights
// (sampleMap must not read it; mapRange bounds nothing with it).
std::shared_ptr<const SampledMap> declaredMap(const TerrainBlock& block);

struct SolvedTerrain {
    SolveTable table;                       // over the checked world, min (0, 0, 0)
    std::shared_ptr<const SampledMap> map;  // the finest level's heights in world voxels
};

// The finest level's height in world voxels, as fields sample it (NAME(wx, wz)), from the maps
// the block's solve made (SolveTable::terrainMaps).
std::shared_ptr<const SampledMap> solvedMap(const TerrainBlock& block, const TerrainMaps& maps);

// Generates the block's maps (terrain::generateTerrain; `runner` runs the erosion steps, empty:
// the host) and voxelises them. Throws LimitError for work past the block's limits.
SolvedTerrain solveTerrain(const TerrainBlock& block, const ErosionRunner& runner = {});

} // namespace voxc::terrain

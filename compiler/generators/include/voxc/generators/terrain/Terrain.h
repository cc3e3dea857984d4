#pragma once
// The whole terrain generator (spec B3.5): the diffusion cascade, then the multigrid erosion
// schedule over the levels that have steps, the Gaussian smoothing between levels, the final drain
// and deposit. Final height H = v_Lmax + N_Lmax + S_h, normalised by max_height.
#include "voxc/generators/terrain/Cascade.h"
#include "voxc/generators/terrain/Erosion.h"

#include <functional>
#include <optional>

namespace voxc::terrain {

// Runs `steps` erosion steps numbered firstStep.. of `level` on the grid in place (drain: drain
// steps), exactly as that many erosionStep calls would: the host loop (runErosionSteps) or a
// device's (voxc/vulkan/GpuErosion.h).
using ErosionRunner = std::function<void(ErosionGrid& grid, const ErosionParams& params, int32_t level,
                                         uint32_t firstStep, uint32_t steps, bool drain)>;
void runErosionSteps(ErosionGrid& grid, const ErosionParams& params, int32_t level, uint32_t firstStep,
                     uint32_t steps, bool drain);

struct ErosionSettings {
    ErosionParams params;
    std::map<int32_t, uint32_t> levelSteps; // level -> steps; levels outside the map's range are rejected
    uint32_t drainSteps = 100;
    bool thesisProlongation = false;        // Alg. 4 instead of bilinear between erosion levels
    ErosionRunner runner;                   // where each level's steps run; empty: runErosionSteps
};

// ErosionSettings from a Table 5.2/5.3 preset; throws ParameterError for an unknown name.
ErosionSettings presetSettings(std::string_view name);

struct TerrainResult {
    Field2 height;     // H, normalised by max_height
    Field2 difference; // S_h (eroded minus original), zero without erosion
    Field2 water;      // water depth left after the drain
    Field2 sediment;   // suspended sediment (zero after the final deposit)
    uint64_t erosionSteps = 0; // steps over all levels, drain included
    uint64_t erosionCellSteps = 0;
    double totalWater = 0.0, totalSediment = 0.0, totalDifference = 0.0; // sums over the final grid (double)
};

// The Fig. 4.3 Gaussian, 5x5 / 273, clamp to edge, taps row-major.
Field2 gaussian5(const Field2& field);

// What generateTerrain checks before any work (ParameterError, LimitError); the rasteriser's
// bound on cell tests (Limits::maxRasterCells) is only known while generating.
void validateTerrain(const TerrainMap& map, const std::optional<ErosionSettings>& erosion, const Limits& limits = {});

// Validates everything before any work (validateTerrain), then generates.
TerrainResult generateTerrain(const TerrainMap& map, const std::optional<ErosionSettings>& erosion, const Limits& limits = {});

} // namespace voxc::terrain

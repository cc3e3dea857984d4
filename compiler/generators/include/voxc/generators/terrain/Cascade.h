#pragma once
// The per-level diffusion cascade (spec B1.5, B3.2): the thesis's non-converged fixed-sweep Jacobi
// cascade, coarse to fine, with cell-centred prolongation between levels. Each sweep is a plain
// loop over the cells in row-major order reading only the previous sweep (ping-pong), in float32
// with the summation orders documented in docs/terrain.md, so a GLSL kernel can match it bitwise.
#include "voxc/generators/terrain/Raster.h"

#include <functional>

namespace voxc::terrain {

// What one level leaves: the diffused terrain v_L, normals and parameters. The noise N_L is
// computed from them by levelNoise, only on the levels that use it (eroded levels and Lmax).
struct LevelFields {
    int32_t level = 0;
    Field2 height;            // v_L, normalised by maxHeight
    Field2 normalX, normalZ;  // diffused, not normalised
    std::array<Field2, kParamCount> params;
};

// One sweep of Eq 4.1: to = alpha * A v + beta * (B v + G) + ((1 - alpha) - beta) * S, A the
// nine-point average, B the upwind guide of B2.8 on the normalised (normalX, normalZ).
void terrainSweep(const LevelSeeds& seeds, const Field2& normalX, const Field2& normalZ, bool isotropicGradient,
                  const Field2& from, Field2& to);

// One sweep of the four-point average; cells with seed[i] != 0 take seedValues instead.
void averageSweep(const std::vector<uint8_t>& seed, const Field2& seedValues, const Field2& from, Field2& to);

// Level L-1 to level L: cell-centred bilinear (9/16, 3/16, 3/16, 1/16, clamp to edge; B2.12), or
// with `thesis` Alg. 4 (which shifts the field half a fine cell towards the origin).
Field2 prolong(const Field2& coarse, bool thesis);

// The noise N_L (normalised by maxHeight) of level `level` at every cell from its diffused parameters (B3.3).
Field2 levelNoise(const TerrainMap& map, int32_t level, const std::array<Field2, kParamCount>& params);

// Runs the cascade Lmin..Lmax, calling onLevel with each level's fields in turn; returns the last.
// Validates the map first (ParameterError, LimitError).
LevelFields runCascade(const TerrainMap& map, const Limits& limits,
                       const std::function<void(const LevelFields&)>& onLevel = {});

} // namespace voxc::terrain

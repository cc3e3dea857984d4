#pragma once
// Pipe-model hydraulic erosion (Mei et al. 2007 with Mathisen's rain/capacity fields and depth
// limit E; spec B3.4). One step is six passes, each a plain loop over the cells in row-major order
// in float32 with a documented operation order (docs/terrain.md, "Erosion"), so a GLSL kernel can
// reproduce it bit for bit. The water boundary is closed: nothing flows out of the grid.
#include "voxc/generators/terrain/Field2.h"
#include "voxc/generators/terrain/Limits.h"

#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string_view>

namespace voxc::terrain {

// `conservative` splats sediment forward (mass-conserving); `mei` samples it backward (Eq 3.27).
enum class Transport : uint8_t { Conservative, Mei };
// `drops`: one random drop per step (Alg. 1); `uniform`: every cell gets dt * uniformRain; `none`.
enum class RainMode : uint8_t { Drops, Uniform, None };

struct ErosionParams {
    float pipeArea = 1.0f;    // A
    float gravity = 4.0f;     // g
    float pipeLength = 1.0f;  // l
    float cellSize = 1.0f;    // l_x = l_y
    float capacity = 1.0f;    // K_c
    float suspension = 0.5f;  // K_s
    float deposition = 0.5f;  // K_d
    float evaporation = 0.1f; // K_e
    float rainMax = 0.5f, rainMin = 0.25f;     // I_max, I_min: water depth a drop adds
    float radiusMax = 32.0f, radiusMin = 16.0f; // R_max, R_min: drop radius in cells
    float dt = 0.1f;
    float depthLimit = 0.15f; // E; infinity disables it
    float minTilt = 0.0f;     // floor on sin(phi); 0 = the thesis
    float uniformRain = 0.0f; // r of RainMode::Uniform
    Transport transport = Transport::Conservative;
    RainMode rain = RainMode::Drops;
    uint32_t seed = 0;
};

// Throws ParameterError naming the first parameter out of range or the unstable combination
// (K_e*dt > 1, K_d*dt > 1, dt <= 0, l <= 0, ...).
void validateErosion(const ErosionParams& params);

// A named parameter set of Table 5.2 with E = 0.15, and its Table 5.3 steps per level.
struct Preset {
    std::string_view name;
    ErosionParams params;
    std::map<int32_t, uint32_t> levelSteps;
};
std::span<const Preset> presets();
const Preset* findPreset(std::string_view name); // nullptr when there is none of that name

// State and inputs of one grid. Inputs: base (terrain height without erosion), rain (w) and
// capacity (s) multipliers. State: S_h (eroded difference), water d, suspended sediment s, outflow
// fluxes. The rest is per-step scratch.
struct ErosionGrid {
    ErosionGrid(int32_t width, int32_t height);
    int32_t width() const { return base.width; }
    int32_t height() const { return base.height; }

    Field2 base, rain, capacity;
    Field2 difference, water, sediment, fluxL, fluxR, fluxT, fluxB;
    Field2 velocityU, velocityV, suspended, differenceNext;
    Field2 surface; // per pass: b + d (flux) or b (erosion), so neighbours read one value
};

// The passes of one step, in the order erosionStep runs them. `level` and `step` key the drop's hash.
void addRain(ErosionGrid& grid, const ErosionParams& params, int32_t level, uint32_t step);
void updateFlux(ErosionGrid& grid, const ErosionParams& params);
void updateWaterAndVelocity(ErosionGrid& grid, const ErosionParams& params);
void erodeAndDeposit(ErosionGrid& grid, const ErosionParams& params);
void transportSediment(ErosionGrid& grid, const ErosionParams& params);
void evaporate(ErosionGrid& grid, float keep); // d *= keep

// The drop of Alg. 1 for (seed, level, step): intensity, radius, centre in cells.
struct Drop {
    float intensity, radius, centreX, centreY;
};
Drop dropAt(const ErosionParams& params, int32_t width, int32_t height, int32_t level, uint32_t step);

// One step; `drain` runs the final drain's form (no rain, d *= 1 - 0.9).
void erosionStep(ErosionGrid& grid, const ErosionParams& params, int32_t level, uint32_t step, bool drain = false);
// Steps firstStep .. firstStep + steps - 1, the same bits as that many erosionStep calls; grids of
// 256 rows or more split each pass between two threads.
void erosionSteps(ErosionGrid& grid, const ErosionParams& params, int32_t level, uint32_t firstStep, uint32_t steps,
                  bool drain);

} // namespace voxc::terrain

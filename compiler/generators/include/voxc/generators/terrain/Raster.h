#pragma once
// Rasterisation of the feature splines into one level's seed images (spec B1.4, B3.1, B2.9-B2.11):
// elevation seeds (Dirichlet cells of the terrain), the gradient bands' alpha/beta/G, the signed
// normal seeds beside the spline line, and the six parameter seeds on the line. Runs on the CPU
// in double; overlaps are averaged in fixed spline order, so the result is deterministic.
#include "voxc/generators/terrain/Field2.h"
#include "voxc/generators/terrain/Map.h"

#include <array>
#include <cstdint>
#include <vector>

namespace voxc::terrain {

// The diffused parameter fields, in this order everywhere (Table 3.1's A, R, D, F, w, s).
enum class Param : uint8_t { Amplitude, Roughness, WarpLow, WarpHigh, Rain, Capacity };
constexpr size_t kParamCount = 6;

struct LevelSeeds {
    int32_t level = 0;
    Field2 elevation; // S / maxHeight on elevation seeds, 0 elsewhere
    Field2 alpha;     // weight of the plain average A v (1 off the splines)
    Field2 beta;      // weight of the guided B v + G (gradient bands only)
    Field2 gradient;  // G: rise per cell, normalised by maxHeight
    Field2 normalX, normalZ;          // summed unit side directions; normalised at use
    std::vector<uint8_t> normalSeed;  // 1 where a normal seed was written
    std::array<Field2, kParamCount> params;
    std::vector<uint8_t> paramSeed;   // 1 where the parameters are fixed

    bool isElevationSeed(size_t i) const { return alpha.values[i] == 0.0f && beta.values[i] == 0.0f; }
};

// Counts cell tests into `rasterCells`, throwing LimitError before a quad would pass limits.maxRasterCells.
LevelSeeds rasteriseLevel(const TerrainMap& map, int32_t level, const Limits& limits, uint64_t& rasterCells);

// The meta point values at spline position u (linear between the neighbouring meta points, clamped at the ends).
MetaPoint metaAt(const Spline& spline, double u);

} // namespace voxc::terrain

#pragma once
// Signed surface propagation (spec A3.6, Becher section 4.5 with A2.4's |value| choice) and the
// separable binomial smoothing of A3.7. float32, fixed orders (docs/curves.md).
#include "voxc/generators/curves/Voxelize.h"

namespace voxc::curves {

enum class PropagateRule { SmallestMagnitude, SignedMin }; // SignedMin: the paper's printed min

// A cell's BFS layer in the fronts: its city-block distance to the nearest seed cell, under
// 3 * 4096 in any box Limits allows (growLayers checks), so 16 bits: half the memory and half
// the traffic of the fronts' layer passes.
using FrontLayer = int16_t;

struct SurfaceField {
    Field3 distance;              // S; +infinity where no 6-path reaches Omega_S (air)
    std::vector<FrontLayer> layer; // BFS layer that set the cell: 0 on Omega_S, -1 never
    int32_t layers = 0;           // the largest layer
};

// The candidate a cell p gets from its set neighbour x along axis `axis` (p = x + sign * e_axis):
// S_x + sign * ((n_p[axis] + n_x[axis]) * 0.5).
// Inline: the surface front calls it for every candidate of every cell.
inline float propagationCandidate(float fromValue, float normalP, float normalX, int32_t sign) {
    const float step = (normalP + normalX) * 0.5f;
    return fromValue + (sign > 0 ? step : -step);
}

// n is the normalised normal field (normalizeField).
SurfaceField propagateSurface(const Constraints& constraints, const Field3& nx, const Field3& ny, const Field3& nz,
                              PropagateRule rule);

// `passes` times [1,2,1]/4 along x, then y, then z, clamp to edge: ((a + 2b) + c) * 0.25.
Field3 smoothBinomial(const Field3& field, int32_t passes);

} // namespace voxc::curves

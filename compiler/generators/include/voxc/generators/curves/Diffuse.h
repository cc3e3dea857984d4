#pragma once
// Normal diffusion in the Perona-Malik mode (spec A3.4, resolving Becher's errors A2.1-A2.3),
// normalisation of the normal field, and the material vote (A3.5). float32, fixed orders
// (docs/curves.md).
#include "voxc/generators/curves/Voxelize.h"

namespace voxc::curves {

// Becher's edge-stopping function g(x) = 1 / (1 + (x/k)^2), computed as 1 / (1 + q*q), q = x/k.
float peronaMalikG(float x, float k);

struct NormalField {
    Field3 x, y, z;
    std::vector<uint8_t> set; // PM mode: 0 where no normal reached (A2.1's explicit unset flag)
};

// (a) BFS fill from Omega_N, (b) `sweeps` Jacobi sweeps of N_i += 1/6 sum_j c_ij (N_j - N_i)
// over set neighbours j, c_ij = g(clamp((1 - n_i.n_j) / 2, 0, 1)) on normalised n.
NormalField peronaMalikNormals(const Constraints& constraints, float k, uint32_t sweeps, const Limits& limits);
// (a) alone: N0 on Omega_N, then layer by layer an unset cell with set neighbours takes the
// normalised sum of their normals (stays unset below 1e-6).
NormalField peronaMalikFill(const Constraints& constraints);
// (b) alone, in place: ping-pong Jacobi sweeps over the set cells off Omega_N; each sweep
// normalises the field first, then updates every such cell from the previous sweep's values.
void peronaMalikSweeps(const Constraints& constraints, NormalField& normals, float k, uint32_t sweeps);

// n = N / |N|, |N| = sqrt((x*x + y*y) + z*z); 0 where |N| < 1e-6 (A3.4).
// The outputs may be the inputs themselves (normalised in place).
void normalizeField(const Field3& x, const Field3& y, const Field3& z, Field3& outX, Field3& outY, Field3& outZ);

struct MaterialField {
    std::vector<uint16_t> material;
    Field3 confidence;          // 0 where unassigned, 1 on Omega_R
    std::vector<uint8_t> assigned;
    int32_t layers = 0;
};

// BFS from Omega_R, each cell set once: argmax_m of the summed confidences of assigned
// neighbours (tie: lowest id), confidence = winning sum / total sum.
MaterialField propagateMaterial(const Constraints& constraints);

} // namespace voxc::curves

#pragma once
// Noise functions over many points at once, for host loops that evaluate a builtin at every cell
// of a box (the curves solve's displacement). Each result equals the builtin's single-point CPU
// evaluation bit for bit (tests/functions NoiseBatch); where the CPU has AVX2, eight points run
// in one vector register (sixteen where it has AVX-512; a short rest in one padded register), with
// the same IEEE operations in the same order (no FMA), and Perlin's permutation read as pairs
// (one gather for the lookups at i and i + 1, as the shaders read it).
#include <cstddef>
#include <cstdint>

namespace voxc {

// out[i] = warped_fbm((x[i], y[i], z[i]), roughness[i], warpLow, warpHigh, seed) for i < n.
void warpedFbmBatch(const float* x, const float* y, const float* z, const float* roughness, float warpLow,
                    float warpHigh, uint32_t seed, size_t n, float* out);

} // namespace voxc

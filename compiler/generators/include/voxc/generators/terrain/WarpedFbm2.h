#pragma once
// Mathisen's 2D warped fBm (thesis Eq 3.11/3.12, spec B3.3): five layers k = 0..4 of
//   r^(-k (1 - R)) S(q_k + (k F + D / (1 + k)) (S(q_k + 50), S(q_k + 150))),  q_k = 2^k p,
// with S(x, y) = perlin3(x, y, 0) of compiler/builtins. Unlike the 3D warped_fbm it has two warp
// components, as the thesis. float32, fixed operation order (docs/terrain.md, "Noise").
#include <cstdint>

namespace voxc::terrain {

float warpedFbm2(float x, float y, float roughness, float warpLow, float warpHigh, uint32_t seed);

} // namespace voxc::terrain

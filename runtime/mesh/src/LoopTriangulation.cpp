#include "LoopTriangulation.h"

#include <limits>

namespace voxc::mesh_tables {

std::optional<std::vector<std::array<size_t, 3>>> triangulateLoop(size_t n, const ChordCost& chordCost,
                                                                  const TriangleAllowed& allowed) {
    constexpr float kForbidden = std::numeric_limits<float>::infinity();
    std::vector<float> cost(n * n, 0.0f);
    std::vector<size_t> split(n * n, 0);
    for (size_t len = 2; len < n; ++len)
        for (size_t i = 0; i + len < n; ++i) {
            const size_t j = i + len;
            float best = kForbidden;
            for (size_t k = i + 1; k < j; ++k) {
                if (!allowed(i, k, j)) continue;
                const float c = cost[i * n + k] + cost[k * n + j];
                if (c < best) {
                    best = c;
                    split[i * n + j] = k;
                }
            }
            // The chord from the first to the last vertex is a side of the loop: it costs nothing.
            cost[i * n + j] = best + (i == 0 && j == n - 1 ? 0.0f : chordCost(i, j));
        }
    if (!(cost[n - 1] < kForbidden)) return std::nullopt;
    std::vector<std::array<size_t, 3>> triangles;
    triangles.reserve(n - 2);
    auto emit = [&](auto&& self, size_t i, size_t j) -> void {
        if (j < i + 2) return;
        const size_t k = split[i * n + j];
        self(self, i, k);
        triangles.push_back({i, k, j});
        self(self, k, j);
    };
    emit(emit, 0, n - 1);
    return triangles;
}

} // namespace voxc::mesh_tables

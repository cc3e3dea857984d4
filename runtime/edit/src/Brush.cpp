#include "voxc/edit/Brush.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>

namespace voxc {

namespace {

// The grid-local voxels of the brush's support, clipped to a grid of `size` at `origin`; empty
// (last < first) when it misses the grid.
VoxelBox supportBox(const Brush& brush, glm::ivec3 origin, glm::ivec3 size) {
    const glm::vec3 reach(brush.radius + 0.5f * brush.softness);
    const glm::ivec3 low(glm::floor(brush.center - reach)), high(glm::ceil(brush.center + reach));
    return {glm::max(low - origin, glm::ivec3(0)), glm::min(high - origin, size - 1)};
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// `density` and `material` map a grid-local voxel to its stored channels.
template <typename Density, typename Material>
std::optional<VoxelBox> applyOver(const Brush& brush, glm::ivec3 origin, glm::ivec3 size, Density&& density,
                                  Material&& material) {
    const bool paints = brush.op == Brush::Op::Add && brush.material != 0;
    const VoxelBox box = supportBox(brush, origin, size);
    std::optional<VoxelBox> changed;
    for (int z = box.first.z; z <= box.last.z; ++z)
        for (int y = box.first.y; y <= box.last.y; ++y)
            for (int x = box.first.x; x <= box.last.x; ++x) {
                const glm::ivec3 local(x, y, z);
                const float b = brushDensity(brush, origin + local);
                if (b == 0.0f) continue; // outside the support: untouched, even a density above 1
                float& d = density(local);
                const float next = brushed(brush.op, d, b);
                uint8_t& id = material(local);
                const bool repaint = paints && next > (std::isfinite(d) ? d : 0.0f) && id != brush.material;
                if (sameBits(next, d) && !repaint) continue;
                d = next;
                if (repaint) id = brush.material;
                if (!changed) changed = VoxelBox{local, local};
                changed->first = glm::min(changed->first, local);
                changed->last = glm::max(changed->last, local);
            }
    return changed;
}

} // namespace

float brushDensity(const Brush& brush, glm::ivec3 p) {
    const glm::vec3 v = glm::vec3(p) - brush.center;
    const float distance = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z) - brush.radius;
    return std::min(std::max(0.5f - distance / brush.softness, 0.0f), 1.0f);
}

float brushed(Brush::Op op, float d, float b) {
    const float density = std::isfinite(d) ? d : 0.0f;
    return op == Brush::Op::Carve ? std::min(density, 1.0f - b) : std::max(density, b);
}

std::optional<VoxelBox> applyBrush(ChunkedGrid& grid, const Brush& brush) {
    // The writes forget the grid's tile ranges; kept and brought up to date over the changed box.
    std::optional<TileRanges> ranges;
    if (const TileRanges* kept = grid.tileRanges()) ranges = *kept;
    const std::optional<VoxelBox> changed =
        applyOver(brush, grid.layout().gridOrigin, grid.layout().gridSize, [&](glm::ivec3 local) -> float& { return grid.at(local); },
                  [&](glm::ivec3 local) -> uint8_t& { return grid.materialAt(local); });
    if (ranges) grid.recordTileRanges(std::move(*ranges), changed ? changed->first : glm::ivec3(0), changed ? changed->last : glm::ivec3(-1));
    return changed;
}

std::optional<VoxelBox> applyBrush(DenseGrid& grid, glm::ivec3 origin, const Brush& brush) {
    return applyOver(brush, origin, grid.size(), [&](glm::ivec3 local) -> float& { return grid.at(local); },
                     [&](glm::ivec3 local) -> uint8_t& { return grid.materialAt(local); });
}

} // namespace voxc

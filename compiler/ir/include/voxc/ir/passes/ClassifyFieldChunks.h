#pragma once
// Interval analysis of a field stage per chunk: evaluates the field's DAG in interval arithmetic
// (voxc/builtins/Intervals.h) over each chunk's box of positions and proves where the field is
// one exact float, so a kernel can skip the DAG there and combine with that constant.
#include "voxc/builtins/Intervals.h"
#include "voxc/ir/Ir.h"

#include <array>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace voxc::ir {

struct FieldChunk {
    glm::ivec3 chunk{0};      // world chunk coordinate (world voxel / chunkSize, rounded down)
    glm::ivec3 localMin{0};   // the chunk's grid voxels: localMin <= local < localMax
    glm::ivec3 localMax{0};
    bool constant = false;    // the field is exactly `value` (bits, signed zero included) at every voxel
    float value = 0.0f;
    // Every value of the field in the chunk lies in [lo, hi] (infinite where unknown, never NaN).
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
};

// Every node's interval where each input (FieldInput order: x, y, z, wx, wy, wz) lies in its
// interval of `inputs`.
std::vector<Interval> fieldNodeIntervals(const IrField& field, const std::array<Interval, 6>& inputs);

// Every chunk of the world's chunk grid that holds grid voxels, x fastest, then y, then z.
std::vector<FieldChunk> classifyFieldChunks(const World& world, const IrField& field);

} // namespace voxc::ir

#pragma once
// The checked model of a speleothem stage (`feature NAME = speleothems { ... }`, docs/language.md
// "Speleothems"): the parameters of lsystem-spec §6.2 with their defaults. The algorithm is
// voxc::caves (compiler/generators, caves/Speleothems.h), its GPU twin compiler/shaders/speleothems.glsl.
#include "voxc/core/SourceLoc.h"
#include "voxc/program/PointSet.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace voxc {

// Which anchors a feature grows from and how thick it is [decide: the spec names stalactite and
// hoodoo; the paper's one-voxel features come from both anchors, so both directions are kinds].
enum class SpeleothemKind : uint8_t {
    Stalactite, // from the ceiling down, one voxel column
    Stalagmite, // from the floor up, one voxel column
    Column,     // both; they join into a column when the reach is 1
    Hoodoo,     // Column, 2 x 2 voxel columns thick: a feature at (x, z) also covers x+1 and z+1
};

// The spec's defaults. Keys as a .vox file writes them are in the comments.
struct SpeleothemParams {
    SpeleothemKind kind = SpeleothemKind::Stalactite; // kind
    float clusterFrequency = 0.02f; // cluster_frequency, [0, 1000]
    float clusterLow = 0.2f;        // cluster_low, [-1, 1], <= cluster_high
    float clusterHigh = 1.0f;       // cluster_high, [-1, 1]
    float spawnFrequency = 0.9f;    // spawn_frequency, [0, 1000]
    float spawnThreshold = 0.55f;   // spawn_threshold, [-1, 0.99]
    float growth = 1.5f;            // growth, [0, 1000]
    // taper, [0, 8]: the exponent of the taper curve. An integer so the GPU computes it with
    // multiplications, bit for bit (pow is not exact) [decide: the spec's taper is real].
    int32_t taper = 1;
    int32_t minGap = 3;             // min_gap, [1, 4096]
    int32_t maxGap = 64;            // max_gap, [min_gap, 4096]
    std::optional<uint8_t> material; // written where a feature wins (voxc::combineField, union)
};

// 1 / (1 - spawn_threshold), rounded once on the host: the reach multiplies by it, so both
// backends perform only correctly rounded additions and multiplications (exact on every Vulkan
// device, where a division may be off by 2.5 ulp).
inline float speleothemReachScale(const SpeleothemParams& params) { return 1.0f / (1.0f - params.spawnThreshold); }

// One declared speleothem feature; a pipeline entry naming it is a Stage::Kind::Speleothems.
struct SpeleothemStage {
    std::string name;
    SourceLoc loc;
    SpeleothemParams params;
    // `keep_clear = CAVE`: the lsystem_cave feature's point set; voxels within its clearance
    // (pointSetClearance) are never written. Null: none.
    std::shared_ptr<const PointSet> clearance;
};

} // namespace voxc

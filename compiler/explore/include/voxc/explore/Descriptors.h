#pragma once
// What one generated volume is reduced to, and statistics over runs (docs/explore.md).
//
// A voxel is solid when its density is >= iso (the language's `GEQ` convention for rock);
// voxels outside the grid count as air.
#include "voxc/grid/Grid.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace voxc::explore {

// The solid voxels of one volume, one bit per voxel in DenseGrid index order.
struct SolidSet {
    glm::ivec3 size{0};
    std::vector<uint64_t> words;
    uint64_t count = 0; // number of solid voxels
};

SolidSet solidSet(const DenseGrid& grid, float iso);

struct VolumeDescriptors {
    // Solid voxels / all voxels, in [0, 1].
    double solidFraction = 0.0;
    // Faces between a solid voxel and an air voxel or the outside of the grid, in voxel faces
    // (1 = one voxel face of area 1): the exact area of the blocky boundary, including where the
    // solid touches the grid's border.
    double surfaceArea = 0.0;
};

VolumeDescriptors describeVolume(const DenseGrid& grid, float iso);

// |A ∩ B| / |A ∪ B|; 1 when both are empty (identical sets). The sizes must match.
double intersectionOverUnion(const SolidSet& a, const SolidSet& b);

struct MeanDeviation {
    double mean = 0.0;
    double stddev = 0.0; // sample standard deviation (divides by n - 1); 0 for one sample
};

MeanDeviation meanDeviation(const std::vector<double>& samples);

// Mean and deviation of the IoU over all n(n-1)/2 pairs of sets; nothing for fewer than two sets.
std::optional<MeanDeviation> pairwiseIou(const std::vector<SolidSet>& sets);

} // namespace voxc::explore

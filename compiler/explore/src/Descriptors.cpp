#include "voxc/explore/Descriptors.h"

#include "voxc/core/Errors.h"

#include <bit>
#include <cmath>

namespace voxc::explore {

SolidSet solidSet(const DenseGrid& grid, float iso) {
    SolidSet set;
    set.size = grid.size();
    const std::vector<float>& data = grid.data();
    set.words.assign((data.size() + 63) / 64, 0);
    for (size_t i = 0; i < data.size(); ++i) {
        if (data[i] >= iso) {
            set.words[i / 64] |= uint64_t(1) << (i % 64);
            ++set.count;
        }
    }
    return set;
}

VolumeDescriptors describeVolume(const DenseGrid& grid, float iso) {
    const glm::ivec3 size = grid.size();
    const std::vector<float>& data = grid.data();
    VolumeDescriptors descriptors;
    if (data.empty()) return descriptors;
    uint64_t solid = 0;
    uint64_t faces = 0;
    auto solidAt = [&](glm::ivec3 p) { return grid.inside(p) && grid.at(p) >= iso; };
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 p{x, y, z};
                if (!solidAt(p)) continue;
                ++solid;
                for (int axis = 0; axis < 3; ++axis)
                    for (int sign : {-1, 1}) {
                        glm::ivec3 q = p;
                        q[axis] += sign;
                        if (!solidAt(q)) ++faces;
                    }
            }
    descriptors.solidFraction = double(solid) / double(data.size());
    descriptors.surfaceArea = double(faces);
    return descriptors;
}

double intersectionOverUnion(const SolidSet& a, const SolidSet& b) {
    VOXC_ASSERT(a.size == b.size && a.words.size() == b.words.size());
    uint64_t intersection = 0;
    uint64_t both = 0;
    for (size_t i = 0; i < a.words.size(); ++i) {
        intersection += uint64_t(std::popcount(a.words[i] & b.words[i]));
        both += uint64_t(std::popcount(a.words[i] | b.words[i]));
    }
    return both == 0 ? 1.0 : double(intersection) / double(both);
}

MeanDeviation meanDeviation(const std::vector<double>& samples) {
    MeanDeviation result;
    if (samples.empty()) return result;
    double sum = 0.0;
    for (double s : samples) sum += s;
    result.mean = sum / double(samples.size());
    if (samples.size() < 2) return result;
    double squares = 0.0;
    for (double s : samples) squares += (s - result.mean) * (s - result.mean);
    result.stddev = std::sqrt(squares / double(samples.size() - 1));
    return result;
}

std::optional<MeanDeviation> pairwiseIou(const std::vector<SolidSet>& sets) {
    if (sets.size() < 2) return std::nullopt;
    std::vector<double> ious;
    ious.reserve(sets.size() * (sets.size() - 1) / 2);
    for (size_t i = 0; i < sets.size(); ++i)
        for (size_t j = i + 1; j < sets.size(); ++j) ious.push_back(intersectionOverUnion(sets[i], sets[j]));
    return meanDeviation(ious);
}

} // namespace voxc::explore

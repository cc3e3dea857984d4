#include "voxc/program/SampledMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxc {

namespace {

// u clamped to [0, last]; u is not NaN.
float clampCell(float u, float last) { return u < 0.0f ? 0.0f : (u > last ? last : u); }

// Boxes of more cells than this are bounded by the whole map's range (a chunk reads about
// chunk² cells; a warped or unbounded coordinate reads everything).
constexpr double kMaxScannedCells = 1 << 16;

} // namespace

float sampleMap(const SampledMap& map, float wx, float wz) {
    if (std::isnan(wx) || std::isnan(wz)) return std::numeric_limits<float>::quiet_NaN();
    const float last = float(map.side - 1);
    const float u = clampCell((wx - map.originX) * map.cellsPerVoxel - 0.5f, last);
    const float v = clampCell((wz - map.originZ) * map.cellsPerVoxel - 0.5f, last);
    const float cellU = std::floor(u), cellV = std::floor(v);
    const int32_t i = int32_t(cellU), j = int32_t(cellV);
    const int32_t i1 = std::min(i + 1, map.side - 1), j1 = std::min(j + 1, map.side - 1);
    const float tx = u - cellU, tz = v - cellV;
    const float sx = 1.0f - tx, sz = 1.0f - tz;
    const float near = sx * map.at(i, j) + tx * map.at(i1, j);
    const float far = sx * map.at(i, j1) + tx * map.at(i1, j1);
    return near * sz + far * tz;
}

MapRange mapRange(const SampledMap& map, double wxLo, double wxHi, double wzLo, double wzHi) {
    if (map.height.empty()) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    // The cells a coordinate range reads (the float rounding of u moves it by far less than a cell).
    const auto cells = [&](double lo, double hi, double origin) {
        const double last = double(map.side - 1);
        const double a = std::clamp((lo - origin) * map.cellsPerVoxel - 0.5, 0.0, last);
        const double b = std::clamp((hi - origin) * map.cellsPerVoxel - 0.5, 0.0, last);
        return std::pair(std::max(0.0, std::floor(a) - 1.0), std::min(last, std::floor(b) + 2.0));
    };
    double lo = map.lowest, hi = map.highest;
    const auto [x0, x1] = cells(wxLo, wxHi, map.originX);
    const auto [z0, z1] = cells(wzLo, wzHi, map.originZ);
    if ((x1 - x0 + 1) * (z1 - z0 + 1) <= kMaxScannedCells) {
        lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (int32_t z = int32_t(z0); z <= int32_t(z1); ++z)
            for (int32_t x = int32_t(x0); x <= int32_t(x1); ++x) {
                lo = std::min(lo, double(map.at(x, z)));
                hi = std::max(hi, double(map.at(x, z)));
            }
    }
    // Weights that sum to 1 within a few roundings: a few ulp of the largest magnitude.
    const double slack = std::max(std::abs(lo), std::abs(hi)) * 0x1p-20 + std::numeric_limits<float>::denorm_min();
    return {lo - slack, hi + slack};
}

} // namespace voxc

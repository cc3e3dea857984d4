#include "voxc/program/SampledMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxc {

namespace {

// u clamped to [0, last]; u is not NaN.
float clampCell(float u, float last) { return u < 0.0f ? 0.0f : (u > last ? last : u); }

// Boxes of more cells than this are bounded by the whole map's range (a chunk reads about
// chunk² cells of a height map, chunk³ of a volume; a warped or unbounded coordinate reads
// everything).
constexpr double kMaxScannedCells = 1 << 16;

// One axis of a sample: the cell, its clamped neighbour and the weight of the neighbour.
struct Axis {
    int32_t i, i1;
    float t;
};
Axis axis(float w, float origin, float cellsPerVoxel, int32_t cells) {
    const float u = clampCell((w - origin) * cellsPerVoxel - 0.5f, float(cells - 1));
    const float cell = std::floor(u);
    const int32_t i = int32_t(cell);
    return {i, std::min(i + 1, cells - 1), u - cell};
}

// The cells a coordinate range reads along one axis (the float rounding of u moves it by far
// less than a cell), one more either side.
std::pair<double, double> cellsRead(double lo, double hi, double origin, double cellsPerVoxel, int32_t cells) {
    const double last = double(cells - 1);
    const double a = std::clamp((lo - origin) * cellsPerVoxel - 0.5, 0.0, last);
    const double b = std::clamp((hi - origin) * cellsPerVoxel - 0.5, 0.0, last);
    return {std::max(0.0, std::floor(a) - 1.0), std::min(last, std::floor(b) + 2.0)};
}

// Weights that sum to 1 within a few roundings: a few ulp of the largest magnitude.
MapRange widened(double lo, double hi) {
    const double slack = std::max(std::abs(lo), std::abs(hi)) * 0x1p-20 + std::numeric_limits<float>::denorm_min();
    return {lo - slack, hi + slack};
}

// The range of a map not solved yet (no values): chunks are computed, never wrongly skipped.
MapRange unbounded() { return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}; }

} // namespace

float sampleMap(const SampledMap& map, float wx, float wz) {
    if (std::isnan(wx) || std::isnan(wz)) return std::numeric_limits<float>::quiet_NaN();
    const Axis x = axis(wx, map.origin.x, map.cellsPerVoxel.x, map.size.x);
    const Axis z = axis(wz, map.origin.z, map.cellsPerVoxel.z, map.size.z);
    const float sx = 1.0f - x.t, sz = 1.0f - z.t;
    const float near = sx * map.at(x.i, z.i) + x.t * map.at(x.i1, z.i);
    const float far = sx * map.at(x.i, z.i1) + x.t * map.at(x.i1, z.i1);
    return near * sz + far * z.t;
}

float sampleVolume(const SampledMap& map, float wx, float wy, float wz) {
    if (std::isnan(wx) || std::isnan(wy) || std::isnan(wz)) return std::numeric_limits<float>::quiet_NaN();
    const Axis x = axis(wx, map.origin.x, map.cellsPerVoxel.x, map.size.x);
    const Axis y = axis(wy, map.origin.y, map.cellsPerVoxel.y, map.size.y);
    const Axis z = axis(wz, map.origin.z, map.cellsPerVoxel.z, map.size.z);
    const float sx = 1.0f - x.t, sy = 1.0f - y.t, sz = 1.0f - z.t;
    const float c00 = sx * map.at(x.i, y.i, z.i) + x.t * map.at(x.i1, y.i, z.i);
    const float c10 = sx * map.at(x.i, y.i1, z.i) + x.t * map.at(x.i1, y.i1, z.i);
    const float c01 = sx * map.at(x.i, y.i, z.i1) + x.t * map.at(x.i1, y.i, z.i1);
    const float c11 = sx * map.at(x.i, y.i1, z.i1) + x.t * map.at(x.i1, y.i1, z.i1);
    const float c0 = c00 * sy + c10 * y.t;
    const float c1 = c01 * sy + c11 * y.t;
    return c0 * sz + c1 * z.t;
}

MapRange mapRange(const SampledMap& map, double wxLo, double wxHi, double wzLo, double wzHi) {
    if (map.values.empty()) return unbounded();
    double lo = map.lowest, hi = map.highest;
    const auto [x0, x1] = cellsRead(wxLo, wxHi, map.origin.x, map.cellsPerVoxel.x, map.size.x);
    const auto [z0, z1] = cellsRead(wzLo, wzHi, map.origin.z, map.cellsPerVoxel.z, map.size.z);
    if ((x1 - x0 + 1) * (z1 - z0 + 1) <= kMaxScannedCells) {
        lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (int32_t z = int32_t(z0); z <= int32_t(z1); ++z)
            for (int32_t x = int32_t(x0); x <= int32_t(x1); ++x) {
                lo = std::min(lo, double(map.at(x, z)));
                hi = std::max(hi, double(map.at(x, z)));
            }
    }
    return widened(lo, hi);
}

MapRange volumeRange(const SampledMap& map, const double lo[3], const double hi[3]) {
    if (map.values.empty()) return unbounded();
    double low = map.lowest, high = map.highest;
    std::pair<double, double> cells[3];
    double count = 1.0;
    for (int a = 0; a < 3; ++a) {
        cells[a] = cellsRead(lo[a], hi[a], map.origin[a], map.cellsPerVoxel[a], map.size[a]);
        count *= cells[a].second - cells[a].first + 1;
    }
    if (count <= kMaxScannedCells) {
        low = std::numeric_limits<double>::infinity(), high = -low;
        for (int32_t z = int32_t(cells[2].first); z <= int32_t(cells[2].second); ++z)
            for (int32_t y = int32_t(cells[1].first); y <= int32_t(cells[1].second); ++y)
                for (int32_t x = int32_t(cells[0].first); x <= int32_t(cells[0].second); ++x) {
                    low = std::min(low, double(map.at(x, y, z)));
                    high = std::max(high, double(map.at(x, y, z)));
                }
    }
    return widened(low, high);
}

} // namespace voxc

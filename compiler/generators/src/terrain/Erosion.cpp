#include "voxc/generators/terrain/Erosion.h"

#include "voxc/core/Simd.h"
#include "voxc/program/Random.h"

#include <algorithm>
#include <array>
#include <barrier>
#include <cmath>
#include <fmt/format.h>
#include <thread>
#include <vector>

namespace voxc::terrain {

namespace {

ErosionParams tableParams(float g, float kc, float ks, float kd, float ke, float iMax, float iMin, float rMax, float rMin, float dt) {
    ErosionParams p;
    p.pipeArea = 1.0f;
    p.gravity = g;
    p.pipeLength = 1.0f;
    p.cellSize = 1.0f;
    p.capacity = kc;
    p.suspension = ks;
    p.deposition = kd;
    p.evaporation = ke;
    p.rainMax = iMax;
    p.rainMin = iMin;
    p.radiusMax = rMax;
    p.radiusMin = rMin;
    p.dt = dt;
    p.depthLimit = 0.15f;
    return p;
}

// Table 5.2 (A = l = l_x = l_y = 1 for all four) and Table 5.3, verbatim.
const std::array<Preset, 4> kPresets{{
    {"fantasy", tableParams(4.36f, 0.9f, 0.7f, 0.882f, 0.12f, 0.4f, 0.24f, 32.0f, 20.8f, 0.2f), {{8, 0}, {9, 547}, {10, 1000}, {11, 0}}},
    {"mountain_range", tableParams(3.48f, 1.0f, 0.525f, 0.812f, 0.15f, 0.5f, 0.276f, 35.0f, 15.0f, 0.2f), {{8, 500}, {9, 500}, {10, 500}, {11, 0}}},
    {"mountain_river", tableParams(6.0f, 1.0f, 1.0f, 1.0f, 0.15f, 0.18f, 0.08f, 50.0f, 16.4f, 0.25f), {{8, 2000}, {9, 2000}, {10, 1000}, {11, 500}}},
    {"combined", tableParams(2.0f, 0.9f, 0.69f, 0.46f, 0.1f, 0.36f, 0.2f, 29.7f, 15.4f, 0.1f), {{8, 1000}, {9, 200}, {10, 100}, {11, 0}}},
}};

// Ranges keep every intermediate float32 value of a step finite (docs/terrain.md, "Value ranges").
// Table 5.2's values are all within a factor 10 of 1; these ranges leave three decades either side.
constexpr float kMaxRate = 1e3f, kMinLength = 1e-3f, kMinDt = 1e-4f, kMaxDt = 1e2f, kMaxRadius = 1e5f;

void requireRange(const char* name, float value, float minimum, float maximum) {
    if (!std::isfinite(value)) throw ParameterError(name, value, "must be finite");
    if (value < minimum || value > maximum) throw ParameterError(name, value, fmt::format("must lie in [{}, {}]", minimum, maximum));
}

// Uniform in [0, 1) with a 24-bit mantissa from the counter hash of (seed, level, step, draw).
float uniform(uint32_t seed, int32_t level, uint32_t step, uint32_t draw) {
    const uint32_t h = mix32(mix32(mix32(mix32(seed) ^ uint32_t(level)) ^ step) ^ draw);
    return float(h >> 8) * 0x1p-24f;
}

} // namespace

std::span<const Preset> presets() { return kPresets; }

const Preset* findPreset(std::string_view name) {
    for (const Preset& preset : kPresets)
        if (preset.name == name) return &preset;
    return nullptr;
}

void validateErosion(const ErosionParams& p) {
    requireRange("dt", p.dt, kMinDt, kMaxDt);
    requireRange("pipe_length", p.pipeLength, kMinLength, kMaxRate);
    requireRange("cell_size", p.cellSize, kMinLength, kMaxRate);
    requireRange("pipe_area", p.pipeArea, 0.0f, kMaxRate);
    requireRange("gravity", p.gravity, 0.0f, kMaxRate);
    requireRange("sediment_capacity", p.capacity, 0.0f, kMaxRate);
    requireRange("suspension_rate", p.suspension, 0.0f, kMaxRate);
    requireRange("deposition_rate", p.deposition, 0.0f, kMaxRate);
    requireRange("evaporation", p.evaporation, 0.0f, kMaxRate);
    requireRange("rain_min", p.rainMin, 0.0f, kMaxRate);
    requireRange("rain_max", p.rainMax, 0.0f, kMaxRate);
    requireRange("radius_min", p.radiusMin, 0.0f, kMaxRadius);
    requireRange("radius_max", p.radiusMax, 0.0f, kMaxRadius);
    requireRange("uniform_rain", p.uniformRain, 0.0f, kMaxRate);
    requireRange("min_tilt", p.minTilt, 0.0f, 1.0f); // a floor on sin(phi)
    if (!(p.depthLimit > 0.0f && (p.depthLimit <= kMaxRate || std::isinf(p.depthLimit))))
        throw ParameterError("E", p.depthLimit, "must lie in (0, 1000], or be infinity to disable the limit");
    if (p.rainMin > p.rainMax) throw ParameterError("rain_min", p.rainMin, fmt::format("must be <= rain_max ({})", p.rainMax));
    if (p.radiusMin > p.radiusMax) throw ParameterError("radius_min", p.radiusMin, fmt::format("must be <= radius_max ({})", p.radiusMax));
    // Stability: evaporation may not remove more water than there is, deposition no more sediment.
    if (p.evaporation * p.dt > 1.0f)
        throw ParameterError("K_e*dt", double(p.evaporation) * p.dt, "must be <= 1, or evaporation makes water negative");
    if (p.deposition * p.dt > 1.0f)
        throw ParameterError("K_d*dt", double(p.deposition) * p.dt, "must be <= 1, or deposition exceeds the suspended sediment");
}

ErosionGrid::ErosionGrid(int32_t width, int32_t height)
    : base(width, height), rain(width, height, 1.0f), capacity(width, height, 1.0f), difference(width, height), water(width, height),
      sediment(width, height), fluxL(width, height), fluxR(width, height), fluxT(width, height), fluxB(width, height),
      velocityU(width, height), velocityV(width, height), suspended(width, height), differenceNext(width, height),
      surface(width, height) {}

Drop dropAt(const ErosionParams& p, int32_t width, int32_t height, int32_t level, uint32_t step) {
    Drop drop;
    drop.intensity = uniform(p.seed, level, step, 0) * (p.rainMax - p.rainMin) + p.rainMin;
    drop.radius = uniform(p.seed, level, step, 1) * (p.radiusMax - p.radiusMin) + p.radiusMin;
    drop.centreX = uniform(p.seed, level, step, 2) * float(width);
    drop.centreY = uniform(p.seed, level, step, 3) * float(height);
    return drop;
}

// The passes below work on a band of rows [y0, y1) each, so a step can split the grid between
// two threads (erosionSteps). Each cell's value is the same float operations in the same order
// whichever band it lies in. Per-cell conditions are selects of values computed unconditionally,
// so the rows' interiors are `omp simd` loops that GCC vectorises (built with -fopenmp-simd
// -fno-trapping-math -fno-math-errno: compiler/generators/CMakeLists.txt), 8 wide in the AVX2
// form of each row kernel where the CPU has it and VOXC_SIMD allows (atHostSimd, voxc/core/Simd.h;
// at most AVX2: the kernels are not built for AVX-512). IEEE add, multiply, divide, sqrt, min and max
// give the same bits at every width, and the build has -ffp-contract=off: no FMA changes a rounding.
namespace {

// The read-only pointers of one row and its neighbour rows, clamped to the grid.
struct Rows {
    size_t at, down, up; // offsets of rows y, max(y - 1, 0), min(y + 1, h - 1)
    bool hasDown, hasUp; // whether those are real neighbours (a closed boundary otherwise)
};

Rows rowsAt(int32_t y, int32_t w, int32_t h) {
    const size_t width = size_t(w);
    return {size_t(y) * width, size_t(std::max(y - 1, 0)) * width, size_t(std::min(y + 1, h - 1)) * width, y > 0, y < h - 1};
}

// The row kernels run columns 1 .. w - 2 in a vectorised loop and the edge columns 0 and w - 1
// (one column when w = 1) through `cell(x)`, which handles a missing left or right neighbour.
template <class Cell> void edgeColumns(int32_t w, Cell cell) {
    cell(0);
    if (w > 1) cell(w - 1);
}

// Rain on rows [y0, y1) (B3.4 step 1; not in the drain): a drop inside its disc, or uniform rain.
VOXC_SIMD_KERNEL void rainRows(ErosionGrid& g, const ErosionParams& p, const Drop& drop, int32_t y0, int32_t y1) {
    const int32_t w = g.width();
    const float radiusSquared = drop.radius * drop.radius, amount = p.dt * p.uniformRain;
    for (int32_t y = y0; y < y1; ++y) {
        const size_t row = size_t(y) * size_t(w);
        float* __restrict water = g.water.values.data() + row;
        const float* __restrict rainAt = g.rain.values.data() + row;
        if (p.rain == RainMode::Uniform) {
            for (int32_t x = 0; x < w; ++x) water[x] = water[x] + amount * rainAt[x];
        } else if (p.rain == RainMode::Drops) {
            const float dy = float(y) - drop.centreY;
            for (int32_t x = 0; x < w; ++x) {
                const float dx = float(x) - drop.centreX;
                water[x] = dx * dx + dy * dy <= radiusSquared ? water[x] + drop.intensity * rainAt[x] : water[x];
            }
        }
    }
}

// The water surface (base + S_h) + d the flux reads.
inline float surfaceLevel(float base, float difference, float water) { return (base + difference) + water; }

// surface = (base + S_h) + d: the channel the device's surface pass writes (the flux rows add it
// where they read it).
VOXC_SIMD_KERNEL void surfaceRows(ErosionGrid& g, int32_t y0, int32_t y1) {
    const size_t first = size_t(y0) * size_t(g.width()), last = size_t(y1) * size_t(g.width());
    const float* __restrict base = g.base.values.data();
    const float* __restrict difference = g.difference.values.data();
    const float* __restrict water = g.water.values.data();
    float* __restrict surface = g.surface.values.data();
    for (size_t i = first; i < last; ++i) surface[i] = surfaceLevel(base[i], difference[i], water[i]);
}

// surface = base + S_h, the bed the erosion's tilt reads.
VOXC_SIMD_KERNEL void bedRows(ErosionGrid& g, int32_t y0, int32_t y1) {
    const size_t first = size_t(y0) * size_t(g.width()), last = size_t(y1) * size_t(g.width());
    const float* __restrict base = g.base.values.data();
    const float* __restrict difference = g.difference.values.data();
    float* __restrict surface = g.surface.values.data();
    for (size_t i = first; i < last; ++i) surface[i] = base[i] + difference[i];
}

struct FluxConstants {
    float coefficient, pipeLength, area, dt;
};

// One cell's outflows (B3.4 step 2); a neighbour outside the grid gets none.
inline void fluxCell(FluxConstants c, float level, float left, float right, float down, float up, bool hasLeft,
                     bool hasRight, bool hasDown, bool hasUp, float d, float& fl, float& fr, float& ft, float& fb) {
    // Every value is computed and then selected (GCC keeps possibly trapping float operations
    // out of conditions, so a condition around one would keep the loop scalar).
    const float toLeft = std::max(0.0f, fl + (c.coefficient * (level - left)) / c.pipeLength);
    const float toRight = std::max(0.0f, fr + (c.coefficient * (level - right)) / c.pipeLength);
    const float toUp = std::max(0.0f, ft + (c.coefficient * (level - up)) / c.pipeLength);
    const float toDown = std::max(0.0f, fb + (c.coefficient * (level - down)) / c.pipeLength);
    const float l = hasLeft ? toLeft : 0.0f, r = hasRight ? toRight : 0.0f, t = hasUp ? toUp : 0.0f, b = hasDown ? toDown : 0.0f;
    const float total = ((l + r) + t) + b;
    // K: the outflow may not drain more than the cell holds (Eq 3.18); 1 * f is f, so K = 1
    // when there is no outflow leaves it as it was.
    const float limit = std::min(1.0f, (d * c.area) / (total * c.dt));
    const float k = total > 0.0f ? limit : 1.0f;
    fl = k * l;
    fr = k * r;
    ft = k * t;
    fb = k * b;
}

VOXC_SIMD_KERNEL void fluxRows(ErosionGrid& g, const ErosionParams& p, int32_t y0, int32_t y1) {
    const FluxConstants c{(p.dt * p.pipeArea) * p.gravity, p.pipeLength, p.cellSize * p.cellSize, p.dt};
    const int32_t w = g.width(), h = g.height();
    for (int32_t y = y0; y < y1; ++y) {
        const Rows rows = rowsAt(y, w, h);
        const float* __restrict b = g.base.values.data() + rows.at;
        const float* __restrict bDown = g.base.values.data() + rows.down;
        const float* __restrict bUp = g.base.values.data() + rows.up;
        const float* __restrict sh = g.difference.values.data() + rows.at;
        const float* __restrict shDown = g.difference.values.data() + rows.down;
        const float* __restrict shUp = g.difference.values.data() + rows.up;
        const float* __restrict d = g.water.values.data() + rows.at;
        const float* __restrict dDown = g.water.values.data() + rows.down;
        const float* __restrict dUp = g.water.values.data() + rows.up;
        float* __restrict fl = g.fluxL.values.data() + rows.at;
        float* __restrict fr = g.fluxR.values.data() + rows.at;
        float* __restrict ft = g.fluxT.values.data() + rows.at;
        float* __restrict fb = g.fluxB.values.data() + rows.at;
        const bool hasDown = rows.hasDown, hasUp = rows.hasUp;
#pragma omp simd
        for (int32_t x = 1; x < w - 1; ++x)
            fluxCell(c, surfaceLevel(b[x], sh[x], d[x]), surfaceLevel(b[x - 1], sh[x - 1], d[x - 1]),
                     surfaceLevel(b[x + 1], sh[x + 1], d[x + 1]), surfaceLevel(bDown[x], shDown[x], dDown[x]),
                     surfaceLevel(bUp[x], shUp[x], dUp[x]), true, true, hasDown, hasUp, d[x], fl[x], fr[x], ft[x], fb[x]);
        edgeColumns(w, [&](int32_t x) { // a missing neighbour gets no flux
            const int32_t left = std::max(x - 1, 0), right = std::min(x + 1, w - 1);
            fluxCell(c, surfaceLevel(b[x], sh[x], d[x]), surfaceLevel(b[left], sh[left], d[left]),
                     surfaceLevel(b[right], sh[right], d[right]), surfaceLevel(bDown[x], shDown[x], dDown[x]),
                     surfaceLevel(bUp[x], shUp[x], dUp[x]), x > 0, x < w - 1, hasDown, hasUp, d[x], fl[x], fr[x], ft[x], fb[x]);
        });
    }
}

struct WaterConstants {
    float dt, area, cellSize, speedLimit, keep;
};

// One cell's water and velocity (B3.4 step 3); `in*` are the neighbours' flows into it (0
// outside the grid). The new depth is multiplied by `keep` (the evaporation, or 1: exact).
inline void waterCell(WaterConstants c, float inRight, float inLeft, float inTop, float inBottom, float fl, float fr,
                      float ft, float fb, float& d, float& u, float& v) {
    const float in = ((inRight + inLeft) + inTop) + inBottom;
    const float out = ((fl + fr) + ft) + fb;
    const float d1 = d;
    const float d2 = d1 + (c.dt * (in - out)) / c.area;
    const float mean = (d1 + d2) * 0.5f;
    const float flowX = 0.5f * ((inRight - fl) + (fr - inLeft));
    const float flowY = 0.5f * ((inTop - fb) + (ft - inBottom));
    const float movingU = std::clamp(flowX / (c.cellSize * mean), -c.speedLimit, c.speedLimit);
    const float movingV = std::clamp(flowY / (c.cellSize * mean), -c.speedLimit, c.speedLimit);
    d = d2 * c.keep;
    u = mean > 1e-6f ? movingU : 0.0f;
    v = mean > 1e-6f ? movingV : 0.0f;
}

// Water and velocity.
VOXC_SIMD_KERNEL void waterRows(ErosionGrid& g, const ErosionParams& p, float keep, int32_t y0, int32_t y1) {
    const WaterConstants c{p.dt, p.cellSize * p.cellSize, p.cellSize, (0.5f * p.cellSize) / p.dt, keep};
    const int32_t w = g.width(), h = g.height();
    for (int32_t y = y0; y < y1; ++y) {
        const Rows rows = rowsAt(y, w, h);
        const float* __restrict fl = g.fluxL.values.data() + rows.at;
        const float* __restrict fr = g.fluxR.values.data() + rows.at;
        const float* __restrict ft = g.fluxT.values.data() + rows.at;
        const float* __restrict fb = g.fluxB.values.data() + rows.at;
        const float* __restrict topBelow = g.fluxT.values.data() + rows.down;  // f_T(x, y - 1)
        const float* __restrict bottomAbove = g.fluxB.values.data() + rows.up; // f_B(x, y + 1)
        float* __restrict d = g.water.values.data() + rows.at;
        float* __restrict u = g.velocityU.values.data() + rows.at;
        float* __restrict v = g.velocityV.values.data() + rows.at;
        const bool hasDown = rows.hasDown, hasUp = rows.hasUp;
#pragma omp simd
        for (int32_t x = 1; x < w - 1; ++x) {
            const float inTop = topBelow[x], inBottom = bottomAbove[x]; // loaded always: the rows exist
            waterCell(c, fr[x - 1], fl[x + 1], hasDown ? inTop : 0.0f, hasUp ? inBottom : 0.0f, fl[x], fr[x], ft[x], fb[x], d[x],
                      u[x], v[x]);
        }
        edgeColumns(w, [&](int32_t x) {
            const float inRight = x > 0 ? fr[x - 1] : 0.0f, inLeft = x < w - 1 ? fl[x + 1] : 0.0f;
            const float inTop = topBelow[x], inBottom = bottomAbove[x];
            waterCell(c, inRight, inLeft, hasDown ? inTop : 0.0f, hasUp ? inBottom : 0.0f, fl[x], fr[x], ft[x], fb[x], d[x], u[x],
                      v[x]);
        });
    }
}

struct ErodeConstants {
    float e, minTilt, capacity, suspend, deposit; // suspend = dt K_s, deposit = dt K_d
    bool limited;
};

// One cell's erosion or deposition (B3.4 step 4); the E clamp is on the amount moved, so
// S_h + s is conserved exactly.
inline void erodeCell(ErodeConstants c, float b, float left, float right, float down, float up, float u, float v,
                      float capacityAt, float sh, float s, float& shNext, float& s1) {
    const float px = std::clamp(b - std::min(left, right), 0.0f, 1.0f);
    const float py = std::clamp(b - std::min(down, up), 0.0f, 1.0f);
    const float q = px * px + py * py;
    const float sinTilt = std::max(std::sqrt(q / (1.0f + q)), c.minTilt);
    const float speed = std::sqrt(u * u + v * v);
    const float roomLeft = std::max(0.0f, (c.e - std::abs(sh)) / c.e);
    const float room = c.limited ? roomLeft : 1.0f;
    const float capacity = (((c.capacity * sinTilt) * speed) * capacityAt) * room;
    const float suspended = std::max(0.0f, std::min(c.suspend * (capacity - s), c.e + sh));
    const float deposited = std::max(0.0f, std::min(c.deposit * (s - capacity), c.e - sh));
    const float eroded = sh - suspended, raised = sh + deposited, carried = s + suspended, dropped = s - deposited;
    shNext = capacity > s ? eroded : raised;
    s1 = capacity > s ? carried : dropped;
}

// Reads the bed b + S_h from base and difference (the bed's additions, done where they are read,
// so the pass needs no other row's output of this step); writes S_h into differenceNext (the
// caller swaps the halves).
VOXC_SIMD_KERNEL void erodeRows(ErosionGrid& g, const ErosionParams& p, int32_t y0, int32_t y1) {
    const ErodeConstants c{p.depthLimit, p.minTilt, p.capacity, p.dt * p.suspension, p.dt * p.deposition, std::isfinite(p.depthLimit)};
    const int32_t w = g.width(), h = g.height();
    for (int32_t y = y0; y < y1; ++y) {
        const Rows rows = rowsAt(y, w, h);
        const float* __restrict b = g.base.values.data() + rows.at;
        const float* __restrict bDown = g.base.values.data() + rows.down;
        const float* __restrict bUp = g.base.values.data() + rows.up;
        const float* __restrict shDown = g.difference.values.data() + rows.down;
        const float* __restrict shUp = g.difference.values.data() + rows.up;
        const float* __restrict u = g.velocityU.values.data() + rows.at;
        const float* __restrict v = g.velocityV.values.data() + rows.at;
        const float* __restrict capacity = g.capacity.values.data() + rows.at;
        const float* __restrict sh = g.difference.values.data() + rows.at;
        const float* __restrict s = g.sediment.values.data() + rows.at;
        float* __restrict shNext = g.differenceNext.values.data() + rows.at;
        float* __restrict s1 = g.suspended.values.data() + rows.at;
#pragma omp simd
        for (int32_t x = 1; x < w - 1; ++x)
            erodeCell(c, b[x] + sh[x], b[x - 1] + sh[x - 1], b[x + 1] + sh[x + 1], bDown[x] + shDown[x], bUp[x] + shUp[x], u[x],
                      v[x], capacity[x], sh[x], s[x], shNext[x], s1[x]);
        edgeColumns(w, [&](int32_t x) {
            const int32_t left = std::max(x - 1, 0), right = std::min(x + 1, w - 1);
            erodeCell(c, b[x] + sh[x], b[left] + sh[left], b[right] + sh[right], bDown[x] + shDown[x], bUp[x] + shUp[x], u[x],
                      v[x], capacity[x], sh[x], s[x], shNext[x], s1[x]);
        });
    }
}

// Mei's backward sample (Eq 3.27): bilinear from the clamped departure point. The four samples
// are gathers (AVX2 `vgatherdps` in the vectorised clone); the float operations are the scalar's.
VOXC_SIMD_KERNEL void transportMeiRows(ErosionGrid& g, const ErosionParams& p, int32_t y0, int32_t y1) {
    const int32_t w = g.width(), h = g.height();
    const float dt = p.dt, cellSize = p.cellSize, right = float(w - 1), top = float(h - 1);
    const float* __restrict s1 = g.suspended.values.data();
    for (int32_t y = y0; y < y1; ++y) {
        const size_t row = size_t(y) * size_t(w);
        const float* __restrict u = g.velocityU.values.data() + row;
        const float* __restrict v = g.velocityV.values.data() + row;
        float* __restrict sediment = g.sediment.values.data() + row;
#pragma omp simd
        for (int32_t x = 0; x < w; ++x) {
            const float sx = std::clamp(float(x) - (u[x] * dt) / cellSize, 0.0f, right);
            const float sy = std::clamp(float(y) - (v[x] * dt) / cellSize, 0.0f, top);
            const int32_t x0 = int32_t(std::floor(sx)), yy0 = int32_t(std::floor(sy));
            const int32_t x1 = std::min(x0 + 1, w - 1), yy1 = std::min(yy0 + 1, h - 1);
            const float fx = sx - float(x0), fy = sy - float(yy0);
            const float low = (1.0f - fx) * s1[yy0 * w + x0] + fx * s1[yy0 * w + x1];
            const float high = (1.0f - fx) * s1[yy1 * w + x0] + fx * s1[yy1 * w + x1];
            sediment[x] = low * (1.0f - fy) + high * fy;
        }
    }
}

// One row of conservative-transport sources, padded by a zero source at columns -1 and w: the
// sediment and, per axis, the weights it gives the cells one before, at and one after it.
struct SourceRow {
    float *sediment, *x[3], *y[3];
};

// The sources of row sy: an arrival t = clamp(x + (u dt)/l_x, 0, W - 1) lies within half a cell
// (the velocity clamp), so floor(t) is x - 1 or x, and the weights 1 - frac(t) and frac(t) land
// on (x - 1, x) or (x, x + 1); the third offset gets 0.
VOXC_SIMD_KERNEL void conservativeSourceRow(const ErosionGrid& g, const ErosionParams& p, int32_t sy, SourceRow out) {
    const int32_t w = g.width(), h = g.height();
    const size_t row = size_t(sy) * size_t(w);
    const float dt = p.dt, cellSize = p.cellSize, right = float(w - 1), top = float(h - 1);
    const float* __restrict s1 = g.suspended.values.data() + row;
    const float* __restrict u = g.velocityU.values.data() + row;
    const float* __restrict v = g.velocityV.values.data() + row;
    float* __restrict sediment = out.sediment + 1;
    float* __restrict x0 = out.x[0] + 1;
    float* __restrict x1 = out.x[1] + 1;
    float* __restrict x2 = out.x[2] + 1;
    float* __restrict wy0 = out.y[0] + 1;
    float* __restrict wy1 = out.y[1] + 1;
    float* __restrict wy2 = out.y[2] + 1;
#pragma omp simd
    for (int32_t x = 0; x < w; ++x) {
        const float tx = std::clamp(float(x) + (u[x] * dt) / cellSize, 0.0f, right);
        const float ty = std::clamp(float(sy) + (v[x] * dt) / cellSize, 0.0f, top);
        const float floorX = std::floor(tx), floorY = std::floor(ty);
        const float fx = tx - floorX, fy = ty - floorY;
        const float restX = 1.0f - fx, restY = 1.0f - fy;
        const bool before = floorX < float(x), below = floorY < float(sy);
        sediment[x] = s1[x];
        x0[x] = before ? restX : 0.0f;
        x1[x] = before ? fx : restX;
        x2[x] = before ? 0.0f : fx;
        wy0[x] = below ? restY : 0.0f;
        wy1[x] = below ? fy : restY;
        wy2[x] = below ? 0.0f : fy;
    }
}

// Adds the three sources x - 1, x, x + 1 of one source row to every cell x of a target row, in
// that order; `dy` is the weight index along y (the target row's offset from the source's + 1).
VOXC_SIMD_KERNEL void gatherSourceRow(float* __restrict target, const SourceRow& source, int dy, int32_t w) {
    const float* __restrict s = source.sediment;
    const float* __restrict x0 = source.x[0];
    const float* __restrict x1 = source.x[1];
    const float* __restrict x2 = source.x[2];
    const float* __restrict ys = source.y[dy];
#pragma omp simd
    for (int32_t x = 0; x < w; ++x) { // padded index x + 1 is source column x
        float sum = target[x];
        sum = sum + s[x] * (x2[x] * ys[x]);
        sum = sum + s[x + 1] * (x1[x + 1] * ys[x + 1]);
        sum = sum + s[x + 2] * (x0[x + 2] * ys[x + 2]);
        target[x] = sum;
    }
}

// The documented gather (B3.4 step 5): cell (x, y) sums its 3x3 sources' contributions
// s1 * (w_x * w_y), sources in row-major order, from +0. A source adds the product for every
// neighbour, weight 0 and sediment 0 included: s1 and the weights are finite, so such a term is
// +-0, and adding +-0 to a sum that is never -0 (it starts at +0, and x + -x is +0) leaves it as
// it was, which is the documented "zero weights skipped" bit for bit. The sources' weights come
// from a ring of three rows in `scratch`; the band [y0, y1) reads sources from rows y0 - 1 to y1.
void transportConservativeRows(ErosionGrid& g, const ErosionParams& p, int32_t y0, int32_t y1, std::vector<float>& scratch) {
    const int32_t w = g.width(), h = g.height();
    const size_t padded = size_t(w) + 2;
    scratch.assign(3 * 7 * padded, 0.0f); // the pads stay 0: a source outside the grid adds +0
    const auto ring = [&](int32_t sy) {
        float* base = scratch.data() + size_t(sy % 3) * 7 * padded;
        return SourceRow{base, {base + padded, base + 2 * padded, base + 3 * padded},
                         {base + 4 * padded, base + 5 * padded, base + 6 * padded}};
    };
    if (y0 > 0) atHostSimd<conservativeSourceRow, Simd::Avx2>(g, p, y0 - 1, ring(y0 - 1));
    atHostSimd<conservativeSourceRow, Simd::Avx2>(g, p, y0, ring(y0));
    for (int32_t y = y0; y < y1; ++y) {
        if (y + 1 < h) atHostSimd<conservativeSourceRow, Simd::Avx2>(g, p, y + 1, ring(y + 1));
        float* target = g.sediment.values.data() + size_t(y) * size_t(w);
        std::fill(target, target + w, 0.0f);
        if (y > 0) atHostSimd<gatherSourceRow, Simd::Avx2>(target, ring(y - 1), 2, w);
        atHostSimd<gatherSourceRow, Simd::Avx2>(target, ring(y), 1, w);
        if (y + 1 < h) atHostSimd<gatherSourceRow, Simd::Avx2>(target, ring(y + 1), 0, w);
    }
}

void transportRows(ErosionGrid& g, const ErosionParams& p, int32_t y0, int32_t y1, std::vector<float>& scratch) {
    if (p.transport == Transport::Mei)
        atHostSimd<transportMeiRows, Simd::Avx2>(g, p, y0, y1);
    else
        transportConservativeRows(g, p, y0, y1, scratch);
}

// Grids with fewer rows run on one thread: a 128-row pass is too short to pay for the
// synchronisation between the passes.
constexpr int32_t kMinRowsForTwoThreads = 256;

} // namespace

void addRain(ErosionGrid& g, const ErosionParams& p, int32_t level, uint32_t step) {
    if (p.rain == RainMode::None) return;
    const Drop drop = p.rain == RainMode::Drops ? dropAt(p, g.width(), g.height(), level, step) : Drop{};
    atHostSimd<rainRows, Simd::Avx2>(g, p, drop, 0, g.height());
}

void updateFlux(ErosionGrid& g, const ErosionParams& p) {
    atHostSimd<surfaceRows, Simd::Avx2>(g, 0, g.height());
    atHostSimd<fluxRows, Simd::Avx2>(g, p, 0, g.height());
}

void updateWaterAndVelocity(ErosionGrid& g, const ErosionParams& p) {
    atHostSimd<waterRows, Simd::Avx2>(g, p, 1.0f, 0, g.height());
}

void erodeAndDeposit(ErosionGrid& g, const ErosionParams& p) {
    atHostSimd<bedRows, Simd::Avx2>(g, 0, g.height());
    atHostSimd<erodeRows, Simd::Avx2>(g, p, 0, g.height());
    std::swap(g.difference, g.differenceNext);
}

void transportSediment(ErosionGrid& g, const ErosionParams& p) {
    std::vector<float> scratch;
    transportRows(g, p, 0, g.height(), scratch);
}

void evaporate(ErosionGrid& g, float keep) {
    for (float& d : g.water.values) d = d * keep;
}

// A step as two passes over a band, each after the previous one has finished on every band:
// the flux, adding the surface (b + S_h) + d where it reads it; then, eight rows at a time,
// water, velocity and evaporation, the next step's rain (it follows the evaporation, as the
// passes one after the other do) and the erosion of the same rows (it reads this band's
// velocities and every row's b + S_h, which no pass of the step has changed yet); then S_h's
// halves swap, and the transport, followed without a wait by the next step's flux: the transport
// writes only the sediment, which the flux does not read, and reads no channel the flux writes.
// The first step's rain runs before the first wait. The last step leaves the bed b + S_h in
// `surface`, as the passes one after the other do.
void erosionSteps(ErosionGrid& g, const ErosionParams& p, int32_t level, uint32_t firstStep, uint32_t steps, bool drain) {
    const float keep = drain ? 1.0f - 0.9f : 1.0f - p.evaporation * p.dt;
    const bool rain = !drain && p.rain != RainMode::None;
    constexpr int32_t kRowsPerChunk = 8;
    const uint32_t end = firstStep + steps;
    const auto dropOf = [&](uint32_t step) {
        return p.rain == RainMode::Drops ? dropAt(p, g.width(), g.height(), level, step) : Drop{};
    };
    const auto band = [&](auto&& wait, int32_t y0, int32_t y1) {
        std::vector<float> scratch; // the conservative transport's source rows
        if (rain && steps > 0) atHostSimd<rainRows, Simd::Avx2>(g, p, dropOf(firstStep), y0, y1);
        wait();
        for (uint32_t step = firstStep; step < end; ++step) {
            atHostSimd<fluxRows, Simd::Avx2>(g, p, y0, y1);
            wait();
            const bool rainNext = rain && step + 1 < end;
            const Drop next = rainNext ? dropOf(step + 1) : Drop{};
            for (int32_t y = y0; y < y1; y += kRowsPerChunk) {
                const int32_t last = std::min(y + kRowsPerChunk, y1);
                atHostSimd<waterRows, Simd::Avx2>(g, p, keep, y, last);
                if (rainNext) atHostSimd<rainRows, Simd::Avx2>(g, p, next, y, last);
                atHostSimd<erodeRows, Simd::Avx2>(g, p, y, last);
            }
            if (step + 1 == end) atHostSimd<bedRows, Simd::Avx2>(g, y0, y1);
            wait(); // S_h's halves swap here
            transportRows(g, p, y0, y1, scratch);
        }
    };
    // Between passes, once every band has arrived (a barrier's completion with two threads): the
    // first wait follows the first rain, then every second is after the erosion.
    uint32_t phase = 0;
    const auto completion = [&]() noexcept {
        if (phase > 0 && phase % 2 == 0) std::swap(g.difference, g.differenceNext);
        ++phase;
    };
    const int32_t h = g.height();
    if (h < kMinRowsForTwoThreads) {
        band(completion, 0, h);
        return;
    }
    std::barrier sync(2, completion);
    const auto wait = [&] { sync.arrive_and_wait(); };
    std::thread other([&] { band(wait, 0, h / 2); });
    band(wait, h / 2, h);
    other.join();
}

void erosionStep(ErosionGrid& g, const ErosionParams& p, int32_t level, uint32_t step, bool drain) {
    erosionSteps(g, p, level, step, 1, drain);
}

} // namespace voxc::terrain

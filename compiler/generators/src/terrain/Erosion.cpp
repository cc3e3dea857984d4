#include "voxc/generators/terrain/Erosion.h"

#include "voxc/program/Random.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

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

// surface = b (+ d when withWater), b = base + S_h, precomputed so every neighbour read is one load.
void computeSurface(ErosionGrid& g, bool withWater) {
    for (size_t i = 0; i < g.surface.values.size(); ++i) {
        const float b = g.base.values[i] + g.difference.values[i];
        g.surface.values[i] = withWater ? b + g.water.values[i] : b;
    }
}

// A flux channel's value at (x, y), 0 outside the grid (closed boundary).
float fluxOrZero(const Field2& flux, int32_t x, int32_t y) {
    return (x < 0 || y < 0 || x >= flux.width || y >= flux.height) ? 0.0f : flux.at(x, y);
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

void addRain(ErosionGrid& g, const ErosionParams& p, int32_t level, uint32_t step) {
    if (p.rain == RainMode::None) return;
    if (p.rain == RainMode::Uniform) {
        const float amount = p.dt * p.uniformRain;
        for (size_t i = 0; i < g.water.values.size(); ++i) g.water.values[i] = g.water.values[i] + amount * g.rain.values[i];
        return;
    }
    const Drop drop = dropAt(p, g.width(), g.height(), level, step);
    const float radiusSquared = drop.radius * drop.radius;
    for (int32_t y = 0; y < g.height(); ++y)
        for (int32_t x = 0; x < g.width(); ++x) {
            const float dx = float(x) - drop.centreX, dy = float(y) - drop.centreY;
            if (dx * dx + dy * dy <= radiusSquared) {
                const size_t i = g.water.index(x, y);
                g.water.values[i] = g.water.values[i] + drop.intensity * g.rain.values[i];
            }
        }
}

void updateFlux(ErosionGrid& g, const ErosionParams& p) {
    const float coefficient = (p.dt * p.pipeArea) * p.gravity;
    const float area = p.cellSize * p.cellSize;
    const int32_t w = g.width(), h = g.height();
    computeSurface(g, true);
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const size_t i = g.water.index(x, y);
            const float d = g.water.values[i];
            const float level = g.surface.values[i];
            auto outflow = [&](float flux, int32_t nx, int32_t ny) {
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) return 0.0f;
                const float drop = level - g.surface.at(nx, ny);
                return std::max(0.0f, flux + (coefficient * drop) / p.pipeLength);
            };
            float fl = outflow(g.fluxL.values[i], x - 1, y), fr = outflow(g.fluxR.values[i], x + 1, y);
            float ft = outflow(g.fluxT.values[i], x, y + 1), fb = outflow(g.fluxB.values[i], x, y - 1);
            const float total = ((fl + fr) + ft) + fb;
            if (total > 0.0f) { // K: the outflow may not drain more than the cell holds (Eq 3.18)
                const float k = std::min(1.0f, (d * area) / (total * p.dt));
                fl = k * fl;
                fr = k * fr;
                ft = k * ft;
                fb = k * fb;
            }
            g.fluxL.values[i] = fl;
            g.fluxR.values[i] = fr;
            g.fluxT.values[i] = ft;
            g.fluxB.values[i] = fb;
        }
}

void updateWaterAndVelocity(ErosionGrid& g, const ErosionParams& p) {
    const float area = p.cellSize * p.cellSize;
    const float speedLimit = (0.5f * p.cellSize) / p.dt;
    for (int32_t y = 0; y < g.height(); ++y)
        for (int32_t x = 0; x < g.width(); ++x) {
            const size_t i = g.water.index(x, y);
            const float fl = g.fluxL.values[i], fr = g.fluxR.values[i], ft = g.fluxT.values[i], fb = g.fluxB.values[i];
            const float inRight = fluxOrZero(g.fluxR, x - 1, y), inLeft = fluxOrZero(g.fluxL, x + 1, y);
            const float inTop = fluxOrZero(g.fluxT, x, y - 1), inBottom = fluxOrZero(g.fluxB, x, y + 1);
            const float in = ((inRight + inLeft) + inTop) + inBottom;
            const float out = ((fl + fr) + ft) + fb;
            const float d1 = g.water.values[i];
            const float d2 = d1 + (p.dt * (in - out)) / area;
            const float mean = (d1 + d2) * 0.5f;
            float u = 0.0f, v = 0.0f;
            if (mean > 1e-6f) {
                const float flowX = 0.5f * ((inRight - fl) + (fr - inLeft));
                const float flowY = 0.5f * ((inTop - fb) + (ft - inBottom));
                u = std::clamp(flowX / (p.cellSize * mean), -speedLimit, speedLimit);
                v = std::clamp(flowY / (p.cellSize * mean), -speedLimit, speedLimit);
            }
            g.water.values[i] = d2;
            g.velocityU.values[i] = u;
            g.velocityV.values[i] = v;
        }
}

void erodeAndDeposit(ErosionGrid& g, const ErosionParams& p) {
    const float e = p.depthLimit;
    const bool limited = std::isfinite(e);
    computeSurface(g, false);
    const Field2& bed = g.surface;
    for (int32_t y = 0; y < g.height(); ++y)
        for (int32_t x = 0; x < g.width(); ++x) {
            const size_t i = g.water.index(x, y);
            const float b = bed.values[i];
            const float px = std::clamp(b - std::min(bed.clamped(x - 1, y), bed.clamped(x + 1, y)), 0.0f, 1.0f);
            const float py = std::clamp(b - std::min(bed.clamped(x, y - 1), bed.clamped(x, y + 1)), 0.0f, 1.0f);
            const float q = px * px + py * py;
            const float sinTilt = std::max(std::sqrt(q / (1.0f + q)), p.minTilt);
            const float u = g.velocityU.values[i], v = g.velocityV.values[i];
            const float speed = std::sqrt(u * u + v * v);
            const float sh = g.difference.values[i], s = g.sediment.values[i];
            const float room = limited ? std::max(0.0f, (e - std::abs(sh)) / e) : 1.0f;
            const float c = (((p.capacity * sinTilt) * speed) * g.capacity.values[i]) * room;
            // The E clamp is on the amount moved, so S_h + s is conserved exactly (B3.4 step 4).
            if (c > s) {
                const float amount = std::max(0.0f, std::min((p.dt * p.suspension) * (c - s), e + sh));
                g.differenceNext.values[i] = sh - amount;
                g.suspended.values[i] = s + amount;
            } else {
                const float amount = std::max(0.0f, std::min((p.dt * p.deposition) * (s - c), e - sh));
                g.differenceNext.values[i] = sh + amount;
                g.suspended.values[i] = s - amount;
            }
        }
    std::swap(g.difference, g.differenceNext);
}

namespace {

// Mei's backward sample (Eq 3.27): bilinear from the clamped departure point.
void transportMei(ErosionGrid& g, const ErosionParams& p) {
    const int32_t w = g.width(), h = g.height();
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const size_t i = g.water.index(x, y);
            const float sx = std::clamp(float(x) - (g.velocityU.values[i] * p.dt) / p.cellSize, 0.0f, float(w - 1));
            const float sy = std::clamp(float(y) - (g.velocityV.values[i] * p.dt) / p.cellSize, 0.0f, float(h - 1));
            const int32_t x0 = int32_t(std::floor(sx)), y0 = int32_t(std::floor(sy));
            const int32_t x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
            const float fx = sx - float(x0), fy = sy - float(y0);
            const Field2& s1 = g.suspended;
            const float low = (1.0f - fx) * s1.at(x0, y0) + fx * s1.at(x1, y0);
            const float high = (1.0f - fx) * s1.at(x0, y1) + fx * s1.at(x1, y1);
            g.sediment.values[i] = low * (1.0f - fy) + high * fy;
        }
}

// Forward splat (B3.4 step 5): each source sends s1 bilinearly to its arrival point clamped into the
// grid; |u dt| <= 0.5 cell keeps every arrival within its 3x3 neighbourhood. Defined as a gather: cell
// (x, y) sums its sources' contributions s1 * (w_x * w_y), w = 1 - frac at floor(arrival) and frac
// one cell further, sources in row-major order, zero weights skipped. Scattering the sources in
// row-major order adds to every cell in exactly that order, so this loop is that gather bit for bit
// (a GPU kernel gathers). A source without sediment adds +0 to a sum that is never -0: skipped.
void transportConservative(ErosionGrid& g, const ErosionParams& p) {
    const int32_t w = g.width(), h = g.height();
    std::fill(g.sediment.values.begin(), g.sediment.values.end(), 0.0f);
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const size_t i = g.water.index(x, y);
            const float sediment = g.suspended.values[i];
            if (sediment == 0.0f) continue;
            const float tx = std::clamp(float(x) + (g.velocityU.values[i] * p.dt) / p.cellSize, 0.0f, float(w - 1));
            const float ty = std::clamp(float(y) + (g.velocityV.values[i] * p.dt) / p.cellSize, 0.0f, float(h - 1));
            const float floorX = std::floor(tx), floorY = std::floor(ty);
            const float fx = tx - floorX, fy = ty - floorY;
            const float wx0 = 1.0f - fx, wy0 = 1.0f - fy;
            const size_t at = g.water.index(int32_t(floorX), int32_t(floorY));
            float* target = g.sediment.values.data();
            target[at] = target[at] + sediment * (wx0 * wy0);
            if (fx != 0.0f) target[at + 1] = target[at + 1] + sediment * (fx * wy0);
            if (fy != 0.0f) {
                target[at + size_t(w)] = target[at + size_t(w)] + sediment * (wx0 * fy);
                if (fx != 0.0f) target[at + size_t(w) + 1] = target[at + size_t(w) + 1] + sediment * (fx * fy);
            }
        }
}

} // namespace

void transportSediment(ErosionGrid& g, const ErosionParams& p) {
    if (p.transport == Transport::Mei)
        transportMei(g, p);
    else
        transportConservative(g, p);
}

void evaporate(ErosionGrid& g, float keep) {
    for (float& d : g.water.values) d = d * keep;
}

void erosionStep(ErosionGrid& g, const ErosionParams& p, int32_t level, uint32_t step, bool drain) {
    if (!drain) addRain(g, p, level, step);
    updateFlux(g, p);
    updateWaterAndVelocity(g, p);
    erodeAndDeposit(g, p);
    transportSediment(g, p);
    evaporate(g, drain ? 1.0f - 0.9f : 1.0f - p.evaporation * p.dt);
}

} // namespace voxc::terrain

#include "voxc/generators/terrain/Raster.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace voxc::terrain {

namespace {

glm::dvec3 bezier(const glm::dvec3* p, double t) {
    const double s = 1.0 - t;
    return s * s * s * p[0] + 3.0 * s * s * t * p[1] + 3.0 * s * t * t * p[2] + t * t * t * p[3];
}

glm::dvec3 bezierTangent(const glm::dvec3* p, double t) {
    const double s = 1.0 - t;
    return 3.0 * s * s * (p[1] - p[0]) + 6.0 * s * t * (p[2] - p[1]) + 3.0 * t * t * (p[3] - p[2]);
}

std::array<double, kParamCount> paramsOf(const MetaPoint& m) {
    return {m.noiseAmplitude, m.noiseRoughness, m.warpLow, m.warpHigh, m.rain, m.capacity};
}

// One spline sample in level-cell coordinates (cell (i, j) has its centre at (i, j)).
struct Sample {
    glm::dvec2 cell;
    glm::dvec2 side;   // unit perpendicular in x-z: the tangent turned towards +z from +x ("left")
    bool hasSide;
    double elevation;  // y / maxHeight
    MetaPoint meta;
};

// Sums and counts per cell; averaged at the end so overlaps are the mean in spline order. Normals
// and parameters are written only near the line (O(samples) cells), so they are kept sparse.
struct Accumulator {
    explicit Accumulator(int32_t n)
        : cells(size_t(n) * size_t(n)), elevationSum(cells, 0.0), elevationCount(cells, 0), bandOwner(cells, kNoBand),
          bandBeta(cells, 0.0), bandGradient(cells, 0.0) {}
    static constexpr int64_t kNoBand = -1, kRemovedBand = -2;
    struct NormalSum {
        glm::dvec2 sum{0.0};
        uint32_t count = 0;
    };
    struct ParamSum {
        std::array<double, kParamCount> sum{};
        uint32_t count = 0;
    };
    size_t cells;
    std::vector<double> elevationSum;
    std::vector<uint32_t> elevationCount;
    std::unordered_map<size_t, NormalSum> normals;
    std::unordered_map<size_t, ParamSum> params;
    std::vector<int64_t> bandOwner; // spline * 2 + side of the band that wrote the cell
    std::vector<double> bandBeta, bandGradient;
};

class LevelRasteriser {
public:
    LevelRasteriser(const TerrainMap& map, int32_t level, const Limits& limits, uint64_t& rasterCells)
        : map_(map), level_(level), n_(int32_t(1) << level), cell_(map.domain.cellSize(level)), limits_(limits),
          rasterCells_(rasterCells), acc_(n_) {}

    // Samples are made one at a time; each consecutive pair is rasterised as a segment.
    void spline(size_t index, const Spline& spline) {
        std::optional<Sample> previous;
        for (uint32_t piece = 0; piece < spline.pieces(); ++piece) {
            const glm::dvec3* points = &spline.controlPoints[3 * size_t(piece)];
            for (uint32_t k = (piece == 0 ? 0 : 1); k <= spline.samplings; ++k) {
                Sample next = sampleAt(spline, points, piece, double(k) / double(spline.samplings));
                if (previous) segment(index, *previous, next);
                previous = std::move(next);
            }
        }
    }

    LevelSeeds finish() const {
        LevelSeeds seeds;
        seeds.level = level_;
        seeds.elevation = seeds.alpha = seeds.beta = seeds.gradient = seeds.normalX = seeds.normalZ = Field2(n_, n_);
        seeds.alpha.values.assign(acc_.cells, 1.0f);
        for (Field2& field : seeds.params) field = Field2(n_, n_);
        seeds.normalSeed.assign(acc_.cells, 0);
        seeds.paramSeed.assign(acc_.cells, 0);
        for (size_t i = 0; i < acc_.cells; ++i) {
            if (acc_.elevationCount[i] > 0) {
                seeds.elevation.values[i] = float(acc_.elevationSum[i] / acc_.elevationCount[i]);
                seeds.alpha.values[i] = 0.0f;
            } else if (acc_.bandOwner[i] >= 0) {
                const float beta = float(acc_.bandBeta[i]);
                seeds.beta.values[i] = beta;
                seeds.alpha.values[i] = 1.0f - beta;
                seeds.gradient.values[i] = float(acc_.bandGradient[i]);
            }
        }
        for (const auto& [i, normal] : acc_.normals) { // each cell on its own: the map's order does not matter
            seeds.normalSeed[i] = 1;
            seeds.normalX.values[i] = float(normal.sum.x / normal.count);
            seeds.normalZ.values[i] = float(normal.sum.y / normal.count);
        }
        for (const auto& [i, param] : acc_.params) {
            seeds.paramSeed[i] = 1;
            for (size_t p = 0; p < kParamCount; ++p) seeds.params[p].values[i] = float(param.sum[p] / param.count);
        }
        return seeds;
    }

private:
    Sample sampleAt(const Spline& spline, const glm::dvec3* points, uint32_t piece, double t) const {
        const glm::dvec3 p = bezier(points, t);
        glm::dvec3 tangent = bezierTangent(points, t);
        // A degenerate tangent (coincident control points) falls back to the chord of the piece.
        if (std::hypot(tangent.x, tangent.z) < 1e-12) tangent = points[3] - points[0];
        const double length = std::hypot(tangent.x, tangent.z);
        Sample sample;
        sample.cell = {(p.x - map_.domain.origin.x) / cell_ - 0.5, (p.z - map_.domain.origin.y) / cell_ - 0.5};
        sample.hasSide = length >= 1e-12;
        sample.side = sample.hasSide ? glm::dvec2(-tangent.z / length, tangent.x / length) : glm::dvec2(0.0);
        sample.elevation = p.y / map_.domain.maxHeight;
        sample.meta = metaAt(spline, double(piece) + t);
        return sample;
    }

    // A segment writes nothing unless its bounding box, grown by everything it may reach (one cell of
    // normal seeds, the radius and the gradient bands), meets the grid; such segments cost nothing.
    void segment(size_t index, const Sample& a, const Sample& b) {
        const double reach = 1.0 + (std::max(a.meta.radius, b.meta.radius) +
                                    std::max({a.meta.left.x, a.meta.right.x, b.meta.left.x, b.meta.right.x})) / cell_;
        const double lowX = std::min(a.cell.x, b.cell.x) - reach, highX = std::max(a.cell.x, b.cell.x) + reach;
        const double lowY = std::min(a.cell.y, b.cell.y) - reach, highY = std::max(a.cell.y, b.cell.y) + reach;
        if (highX < -0.5 || highY < -0.5 || lowX > n_ - 0.5 || lowY > n_ - 0.5) return;
        line(a, b);
        if (a.hasSide && b.hasSide) {
            if (a.meta.radius > 0.0 || b.meta.radius > 0.0) radiusQuad(a, b);
            band(index * 2, a, b, +1.0, a.meta.left, b.meta.left);
            band(index * 2 + 1, a, b, -1.0, a.meta.right, b.meta.right);
        }
    }

    bool inside(int64_t x, int64_t y) const { return x >= 0 && y >= 0 && x < n_ && y < n_; }
    size_t at(int64_t x, int64_t y) const { return size_t(x) + size_t(n_) * size_t(y); }

    void charge(uint64_t cells) {
        rasterCells_ += cells;
        if (rasterCells_ > limits_.maxRasterCells) throw LimitError("rasterised cell tests", rasterCells_, limits_.maxRasterCells);
    }

    // Bresenham from a to b; elevation and parameters interpolated linearly; normal seeds one cell to each side.
    void line(const Sample& a, const Sample& b) {
        // Validated coordinates (|x| <= 1e9 voxels, cells >= 1e-3 / 4096 voxels) keep cell indices far inside int64.
        const glm::dvec2 fa{std::round(a.cell.x), std::round(a.cell.y)}, fb{std::round(b.cell.x), std::round(b.cell.y)};
        int64_t x0 = int64_t(fa.x), y0 = int64_t(fa.y);
        const int64_t x1 = int64_t(fb.x), y1 = int64_t(fb.y);
        const int64_t dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
        const int64_t sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
        const int64_t steps = std::max(dx, -dy);
        charge(uint64_t(steps) + 1);
        const std::array<double, kParamCount> pa = paramsOf(a.meta), pb = paramsOf(b.meta);
        int64_t error = dx + dy;
        for (int64_t step = 0;; ++step) {
            const double t = steps == 0 ? 0.0 : double(step) / double(steps);
            if (inside(x0, y0)) {
                const size_t i = at(x0, y0);
                acc_.elevationSum[i] += a.elevation + t * (b.elevation - a.elevation);
                ++acc_.elevationCount[i];
                Accumulator::ParamSum& param = acc_.params[i];
                for (size_t p = 0; p < kParamCount; ++p) param.sum[p] += pa[p] + t * (pb[p] - pa[p]);
                ++param.count;
            }
            const glm::dvec2 side = a.side + t * (b.side - a.side);
            const double sideLength = std::hypot(side.x, side.y);
            if (a.hasSide && b.hasSide && sideLength >= 1e-12) {
                normalSeed(x0, y0, side / sideLength);
                normalSeed(x0, y0, -side / sideLength);
            }
            if (x0 == x1 && y0 == y1) break;
            const int64_t twice = 2 * error;
            if (twice >= dy) { error += dy; x0 += sx; }
            if (twice <= dx) { error += dx; y0 += sy; }
        }
    }

    void normalSeed(int64_t x, int64_t y, glm::dvec2 direction) {
        const int64_t nx = x + int64_t(std::lround(direction.x)), ny = y + int64_t(std::lround(direction.y));
        if (!inside(nx, ny)) return;
        const size_t i = at(nx, ny);
        Accumulator::NormalSum& normal = acc_.normals[i];
        normal.sum += direction;
        ++normal.count;
    }

    // Calls visit(cell index, barycentric weights) for every cell centre in the triangle (p0, p1, p2).
    template <class Visit>
    void triangle(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, Visit&& visit) {
        const double det = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
        if (!(std::abs(det) >= 1e-12)) return;
        // The box is clamped into the grid in double before the casts.
        const double last = double(n_ - 1);
        const auto xMin = int64_t(std::clamp(std::ceil(std::min({p0.x, p1.x, p2.x}) - 1e-9), 0.0, last + 1.0));
        const auto xMax = int64_t(std::clamp(std::floor(std::max({p0.x, p1.x, p2.x}) + 1e-9), -1.0, last));
        const auto yMin = int64_t(std::clamp(std::ceil(std::min({p0.y, p1.y, p2.y}) - 1e-9), 0.0, last + 1.0));
        const auto yMax = int64_t(std::clamp(std::floor(std::max({p0.y, p1.y, p2.y}) + 1e-9), -1.0, last));
        if (xMin > xMax || yMin > yMax) return;
        charge(uint64_t(xMax - xMin + 1) * uint64_t(yMax - yMin + 1));
        for (int64_t y = yMin; y <= yMax; ++y)
            for (int64_t x = xMin; x <= xMax; ++x) {
                const double px = double(x) - p0.x, py = double(y) - p0.y;
                const double w1 = (px * (p2.y - p0.y) - (p2.x - p0.x) * py) / det;
                const double w2 = ((p1.x - p0.x) * py - px * (p1.y - p0.y)) / det;
                const double w0 = 1.0 - w1 - w2;
                if (w0 >= -1e-9 && w1 >= -1e-9 && w2 >= -1e-9) visit(at(x, y), glm::dvec3(w0, w1, w2));
            }
    }

    // The flat band of half-width r on both sides: elevation seeds (constant across, linear along).
    void radiusQuad(const Sample& a, const Sample& b) {
        const double ra = a.meta.radius / cell_, rb = b.meta.radius / cell_;
        const glm::dvec2 a0 = a.cell + ra * a.side, a1 = a.cell - ra * a.side;
        const glm::dvec2 b0 = b.cell + rb * b.side, b1 = b.cell - rb * b.side;
        auto write = [&](double e0, double e1, double e2) {
            return [&, e0, e1, e2](size_t i, glm::dvec3 w) {
                acc_.elevationSum[i] += w.x * e0 + w.y * e1 + w.z * e2;
                ++acc_.elevationCount[i];
            };
        };
        triangle(a0, a1, b1, write(a.elevation, a.elevation, b.elevation));
        triangle(a0, b1, b0, write(a.elevation, b.elevation, b.elevation));
    }

    // A gradient band on one side (sign +1: left/a, -1: right/b): beta falls from h at the radius edge
    // to 0 at the outer edge (B2.9); G = (rise / width) * cellSize / maxHeight per cell (B2.10). A band
    // narrower than a cell rises over one cell (width >= cellSize in G), so |G| <= |rise| / maxHeight.
    void band(size_t owner, const Sample& a, const Sample& b, double sign, glm::dvec2 sideA, glm::dvec2 sideB) {
        if (sideA.x <= 0.0 && sideB.x <= 0.0) return;
        const double ra = a.meta.radius / cell_, rb = b.meta.radius / cell_;
        const glm::dvec2 inA = a.cell + sign * ra * a.side, outA = a.cell + sign * (ra + sideA.x / cell_) * a.side;
        const glm::dvec2 inB = b.cell + sign * rb * b.side, outB = b.cell + sign * (rb + sideB.x / cell_) * b.side;
        const double slopeA = sideA.x > 0.0 ? sideA.y / std::max(sideA.x, cell_) * cell_ / map_.domain.maxHeight : 0.0;
        const double slopeB = sideB.x > 0.0 ? sideB.y / std::max(sideB.x, cell_) * cell_ / map_.domain.maxHeight : 0.0;
        auto write = [&](glm::dvec3 beta, glm::dvec3 slope) {
            return [&, beta, slope](size_t i, glm::dvec3 w) {
                int64_t& current = acc_.bandOwner[i];
                if (current == Accumulator::kRemovedBand || current == int64_t(owner)) return; // first write of a band wins
                if (current != Accumulator::kNoBand) { current = Accumulator::kRemovedBand; return; } // two bands overlap
                current = int64_t(owner);
                acc_.bandBeta[i] = glm::dot(w, beta);
                acc_.bandGradient[i] = glm::dot(w, slope);
            };
        };
        const double hA = a.meta.hardness, hB = b.meta.hardness;
        triangle(inA, outA, outB, write({hA, 0.0, 0.0}, {slopeA, slopeA, slopeB}));
        triangle(inA, outB, inB, write({hA, 0.0, hB}, {slopeA, slopeB, slopeB}));
    }

    const TerrainMap& map_;
    int32_t level_;
    int32_t n_;
    double cell_;
    const Limits& limits_;
    uint64_t& rasterCells_;
    Accumulator acc_;
};

} // namespace

MetaPoint metaAt(const Spline& spline, double u) {
    const std::vector<MetaPoint>& metas = spline.metaPoints;
    if (metas.empty()) return MetaPoint{u};
    if (u <= metas.front().u) return metas.front();
    if (u >= metas.back().u) return metas.back();
    size_t next = 1;
    while (metas[next].u < u) ++next;
    const MetaPoint& a = metas[next - 1];
    const MetaPoint& b = metas[next];
    const double t = b.u > a.u ? (u - a.u) / (b.u - a.u) : 0.0;
    auto mix = [t](double x, double y) { return x + t * (y - x); };
    MetaPoint m;
    m.u = u;
    m.radius = mix(a.radius, b.radius);
    m.left = {mix(a.left.x, b.left.x), mix(a.left.y, b.left.y)};
    m.right = {mix(a.right.x, b.right.x), mix(a.right.y, b.right.y)};
    m.hardness = mix(a.hardness, b.hardness);
    m.noiseAmplitude = mix(a.noiseAmplitude, b.noiseAmplitude);
    m.noiseRoughness = mix(a.noiseRoughness, b.noiseRoughness);
    m.warpLow = mix(a.warpLow, b.warpLow);
    m.warpHigh = mix(a.warpHigh, b.warpHigh);
    m.rain = mix(a.rain, b.rain);
    m.capacity = mix(a.capacity, b.capacity);
    return m;
}

LevelSeeds rasteriseLevel(const TerrainMap& map, int32_t level, const Limits& limits, uint64_t& rasterCells) {
    LevelRasteriser rasteriser(map, level, limits, rasterCells);
    for (size_t s = 0; s < map.splines.size(); ++s)
        if (map.splines[s].activeOn(level)) rasteriser.spline(s, map.splines[s]);
    return rasteriser.finish();
}

} // namespace voxc::terrain

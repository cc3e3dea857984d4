#include "voxc/generators/curves/Voxelize.h"

#include "HeapReuse.h"
#include "Parallel.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

namespace voxc::curves {

bool GatheredConstraints::anySurface() const {
    return std::any_of(cells.begin(), cells.end(), [](const Cell& c) { return (c.flags & kInSurface) != 0; });
}

Constraints::Constraints(const GatheredConstraints& gathered) : Constraints(gathered.box) {
    for (const GatheredConstraints::Cell& c : gathered.cells) {
        flags[c.index] = c.flags;
        normalX.values[c.index] = c.normal.x;
        normalY.values[c.index] = c.normal.y;
        normalZ.values[c.index] = c.normal.z;
        amplitude.values[c.index] = c.amplitude;
        roughness.values[c.index] = c.roughness;
        material[c.index] = c.material;
        surface.values[c.index] = c.surface;
    }
}

Constraints::Constraints(const Box& box_) : box(box_) {
    // 27 bytes a box cell, from the heap in huge pages where a solve runs (HeapReuse.h), allocated
    // on this thread (its heap) and zeroed on two: the kernel clears every fresh page as it is
    // first touched, which at 256x128x256 takes longer than gathering the cells.
    const size_t cells = box.cellCount();
    flags.reserve(cells);
    material.reserve(cells);
    for (Field3* field : {&normalX, &normalY, &normalZ, &amplitude, &roughness, &surface}) {
        field->box = box;
        field->values.reserve(cells);
    }
    bothOf(
        [&] {
            flags.resize(cells, 0);
            for (Field3* field : {&normalX, &normalY, &normalZ}) field->values.resize(cells, 0.0f);
        },
        [&] {
            material.resize(cells, 0);
            for (Field3* field : {&amplitude, &roughness, &surface}) field->values.resize(cells, 0.0f);
        });
}

bool triangleOverlapsCube(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& centre, double side) {
    const double h = 0.5 * side;
    const glm::dvec3 v[3] = {triangle[0] - centre, triangle[1] - centre, triangle[2] - centre};
    const glm::dvec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    auto separates = [&](const glm::dvec3& axis) {
        const double p0 = glm::dot(v[0], axis), p1 = glm::dot(v[1], axis), p2 = glm::dot(v[2], axis);
        const double r = h * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    // 13 candidate axes: the cube's faces, the triangle's plane, and edge x edge. A zero axis
    // (parallel edges) projects everything to 0 and never separates.
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 axis(0.0);
        axis[a] = 1.0;
        if (separates(axis)) return false;
        for (const glm::dvec3& e : edges)
            if (separates(glm::cross(axis, e))) return false;
    }
    return !separates(glm::cross(edges[0], edges[1]));
}

glm::dvec3 closestBarycentric(const std::array<glm::dvec3, 3>& tri, const glm::dvec3& p) {
    const glm::dvec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const glm::dvec3 n = glm::cross(e1, e2);
    const double area2 = glm::dot(n, n);
    if (area2 > 1e-24) {
        // Barycentric coordinates of p's projection q onto the plane: q - v0 = b1 e1 + b2 e2.
        const glm::dvec3 q = p - (glm::dot(p - tri[0], n) / area2) * n;
        const double b1 = glm::dot(glm::cross(q - tri[0], e2), n) / area2;
        const double b2 = glm::dot(glm::cross(e1, q - tri[0]), n) / area2;
        const double b0 = 1.0 - b1 - b2;
        if (b0 >= 0.0 && b1 >= 0.0 && b2 >= 0.0) return {b0, b1, b2};
    }
    glm::dvec3 best(1.0, 0.0, 0.0);
    double bestDistance = INFINITY;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const glm::dvec3 d = tri[size_t(j)] - tri[size_t(i)];
        const double len2 = glm::dot(d, d);
        const double s = len2 > 0.0 ? std::clamp(glm::dot(p - tri[size_t(i)], d) / len2, 0.0, 1.0) : 0.0;
        const double distance = glm::length(tri[size_t(i)] + s * d - p);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = glm::dvec3(0.0);
            best[i] = 1.0 - s;
            best[j] = s;
        }
    }
    return best;
}

void checkBox(const Box& box, const Limits& limits) {
    for (int a = 0; a < 3; ++a) {
        if (box.size[a] < 1 || box.size[a] > limits.maxBoxAxis)
            throw ParameterError(fmt::format("box size[{}]", a), box.size[a], fmt::format("must lie in [1, {}]", limits.maxBoxAxis));
        if (std::abs(double(box.min[a])) > limits.maxCoordinate)
            throw ParameterError(fmt::format("box min[{}]", a), box.min[a],
                                 fmt::format("magnitude must be <= {}", limits.maxCoordinate));
    }
    if (box.cellCount() > limits.maxBoxCells) throw LimitError("solve box cells", box.cellCount(), limits.maxBoxCells);
}

namespace {

// One cell's gathered values, summed in triangle order. Its materials' counts are a list in its
// slab's pool (a cell meets one or two materials, so a walk beats a map).
struct Gather {
    glm::dvec3 normal{0.0};
    double amplitude = 0.0, roughness = 0.0, surface = 0.0;
    uint32_t count = 0, seeds = 0;
    uint32_t materials = UINT32_MAX; // the first MaterialCount, or none
};

struct MaterialCount {
    uint16_t material = 0;
    uint32_t count = 0;
    uint32_t next = UINT32_MAX;
};

// Range of cells whose cube can meet [lo, hi] (box-local) on one axis, clamped to the box (empty: first > last).
std::pair<int64_t, int64_t> cellRange(double lo, double hi, int32_t size) {
    const int64_t first = std::max<int64_t>(0, int64_t(std::ceil(lo - 0.5)));
    const int64_t last = std::min<int64_t>(size - 1, int64_t(std::floor(hi + 0.5)));
    return {first, last};
}

// A triangle ready to gather: its corners, the cells its bounds cover, and the unit normal a seed
// triangle measures its plane distance along.
struct PlacedTriangle {
    const RibbonTriangle* tri;
    std::array<glm::dvec3, 3> p;
    std::pair<int64_t, int64_t> range[3];
    glm::dvec3 seedNormal{0.0};
};

// Box cell -> the index of its Gather: open addressing with linear probing, grown at half full.
// Its memory follows the cells hit (a ribbon's), not the box (a dense index would touch 4 bytes
// a box cell, 32 MiB of fresh pages at 256x128x256).
class CellSlots {
public:
    CellSlots() : keys_(1024, kEmpty), values_(1024) {}

    // The slot of `cell`, and whether it was just added (its value then to be set).
    std::pair<uint32_t*, bool> find(size_t cell) {
        if (2 * (size_ + 1) > keys_.size()) grow();
        size_t i = position(cell);
        for (; keys_[i] != kEmpty; i = (i + 1) & (keys_.size() - 1))
            if (keys_[i] == cell) return {&values_[i], false};
        keys_[i] = cell;
        ++size_;
        return {&values_[i], true};
    }

private:
    static constexpr size_t kEmpty = SIZE_MAX;

    size_t position(size_t cell) const {
        return size_t((uint64_t(cell) * 0x9E3779B97F4A7C15ull) >> 32) & (keys_.size() - 1);
    }
    void grow() {
        std::vector<size_t> keys(2 * keys_.size(), kEmpty);
        std::vector<uint32_t> values(keys.size());
        keys_.swap(keys), values_.swap(values);
        for (size_t j = 0; j < keys.size(); ++j) {
            if (keys[j] == kEmpty) continue;
            size_t i = position(keys[j]);
            while (keys_[i] != kEmpty) i = (i + 1) & (keys_.size() - 1);
            keys_[i] = keys[j];
            values_[i] = values[j];
        }
    }

    std::vector<size_t> keys_;
    std::vector<uint32_t> values_;
    size_t size_ = 0;
};

// The gathered cells of the slices [zBegin, zEnd), in the order they were first hit.
class GatheredSlab {
public:
    GatheredSlab(const Box& box, int32_t zBegin, int32_t zEnd) : box_(box), zBegin_(zBegin), zEnd_(zEnd) {}

    // Gathers each triangle in the order given into the cells of this slab it overlaps (with
    // `allowed`, only the cells it marks). Stops once it would hold more than `maxCells` cells:
    // the caller reports the limit.
    void gather(const std::vector<PlacedTriangle>& triangles, SeedValue seedValue, const std::vector<uint8_t>* allowed,
                uint64_t maxCells) {
        for (const PlacedTriangle& placed : triangles) {
            std::pair<int64_t, int64_t> range[3] = {placed.range[0], placed.range[1], placed.range[2]};
            range[2].first = std::max<int64_t>(range[2].first, zBegin_);
            range[2].second = std::min<int64_t>(range[2].second, zEnd_ - 1);
            const RibbonTriangle& tri = *placed.tri;
            const std::array<glm::dvec3, 3>& p = placed.p;
            // Only cells whose cube meets the triangle's plane can meet the triangle: along the
            // axis `d` its normal leans on most, a line of cells crosses the plane's slab
            // |n.(c - p0)| <= (|nx| + |ny| + |nz|) / 2 over an interval, widened a cell each way
            // against rounding. The exact test below decides; this only skips cells it would reject.
            const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            const glm::dvec3 m = glm::abs(n);
            const int d = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
            const int a = (d + 1) % 3, b = (d + 2) % 3;
            const double reach = 0.5 * (m.x + m.y + m.z);
            glm::dvec3 centre;
            for (int64_t j = range[b].first; j <= range[b].second; ++j)
                for (int64_t i = range[a].first; i <= range[a].second; ++i) {
                    int64_t first = range[d].first, last = range[d].second;
                    if (m[d] > 0.0) {
                        // n[d] t + rest within [-reach, reach]
                        const double rest = n[a] * (double(i) - p[0][a]) + n[b] * (double(j) - p[0][b]) - n[d] * p[0][d];
                        const double t0 = (-reach - rest) / n[d], t1 = (reach - rest) / n[d];
                        const double lo = std::min(t0, t1), hi = std::max(t0, t1);
                        if (!(lo <= hi)) continue; // not finite
                        const double begin = double(first), end = double(last); // clamped before converting
                        first = int64_t(std::clamp(std::ceil(lo) - 1.0, begin, end + 1.0));
                        last = int64_t(std::clamp(std::floor(hi) + 1.0, begin - 1.0, end));
                    }
                    centre[a] = double(i), centre[b] = double(j);
                    for (int64_t t = first; t <= last; ++t) {
                        centre[d] = double(t);
                        const size_t index = box_.index(int32_t(centre.x), int32_t(centre.y), int32_t(centre.z));
                        if (allowed && !(*allowed)[index]) continue;
                        if (!triangleOverlapsCube(p, centre, 1.0)) continue;
                        const auto [slot, added] = slots_.find(index);
                        if (added) {
                            if (gathers_.size() == maxCells) {
                                gathers_.emplace_back(); // one past the limit: the caller reports it
                                return;
                            }
                            *slot = uint32_t(gathers_.size());
                            gathers_.emplace_back();
                            cells_.push_back(index);
                        }
                        Gather& g = gathers_[*slot];
                        const glm::dvec3 w = closestBarycentric(p, centre);
                        g.normal += w[0] * tri.v[0].normal + w[1] * tri.v[1].normal + w[2] * tri.v[2].normal;
                        g.amplitude += w[0] * tri.v[0].amplitude + w[1] * tri.v[1].amplitude + w[2] * tri.v[2].amplitude;
                        g.roughness += w[0] * tri.v[0].roughness + w[1] * tri.v[1].roughness + w[2] * tri.v[2].roughness;
                        ++g.count;
                        countMaterial(g, tri.material);
                        if (tri.seed) {
                            g.surface += seedValue == SeedValue::Zero ? 0.0 : glm::dot(placed.seedNormal, centre - p[0]);
                            ++g.seeds;
                        }
                    }
                }
        }
    }

    size_t size() const { return gathers_.size(); }
    const std::vector<size_t>& cells() const { return cells_; }
    const Gather& gather(size_t i) const { return gathers_[i]; }

    // The most counted material of a gather, the lowest id on a tie.
    uint16_t mostCounted(const Gather& g) const {
        uint16_t best = 0;
        uint32_t bestCount = 0;
        for (uint32_t m = g.materials; m != UINT32_MAX; m = materials_[m].next) {
            const MaterialCount& c = materials_[m];
            if (c.count > bestCount || (c.count == bestCount && c.material < best)) best = c.material, bestCount = c.count;
        }
        return best;
    }

private:
    void countMaterial(Gather& g, uint16_t material) {
        for (uint32_t m = g.materials; m != UINT32_MAX; m = materials_[m].next)
            if (materials_[m].material == material) {
                ++materials_[m].count;
                return;
            }
        materials_.push_back(MaterialCount{material, 1, g.materials});
        g.materials = uint32_t(materials_.size() - 1);
    }

    const Box& box_;
    int32_t zBegin_, zEnd_;
    CellSlots slots_;
    std::vector<Gather> gathers_;
    std::vector<size_t> cells_; // the box cell of each gather
    std::vector<MaterialCount> materials_;
};

// Gathers triangles into their cells, each cell in the order the triangles are added, counting
// the overlap tests against Limits::maxCellTests and the cells hit against
// Limits::maxConstrainedCells. A batch of triangles is gathered by two threads, each over its own
// z slices: a cell's sums are the same bits as one thread's, and the limits trip as they would
// adding one triangle at a time (the tests one before the first triangle past it is gathered).
class Gatherer {
public:
    Gatherer(const Box& box, SeedValue seedValue, const Limits& limits)
        : box_(box), seedValue_(seedValue), limits_(limits) {
        forTwoSlabs(box.size.z, kMinimumSlices, [&](int32_t z0, int32_t z1) {
            // Built on the thread that fills it (its pages land in that thread's memory).
            (z0 == 0 ? lower_ : upper_).emplace(box, z0, z1);
        });
    }

    // Queues a triangle; `gather` gathers the queue.
    void add(const RibbonTriangle& tri) {
        PlacedTriangle placed{&tri, {tri.v[0].position, tri.v[1].position, tri.v[2].position}, {}, {}};
        const std::array<glm::dvec3, 3>& p = placed.p;
        const glm::dvec3 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
        uint64_t count = 1;
        for (int a = 0; a < 3; ++a) {
            placed.range[a] = cellRange(lo[a], hi[a], box_.size[a]);
            count *= uint64_t(std::max<int64_t>(0, placed.range[a].second - placed.range[a].first + 1));
        }
        if (testsPast_) return;
        tests_ += count;
        if (tests_ > limits_.maxCellTests) {
            testsPast_ = tests_; // reported once the triangles before it are gathered
            return;
        }
        if (count == 0) return;
        if (tri.seed) {
            glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
            const glm::dvec3 vertexNormals = tri.v[0].normal + tri.v[1].normal + tri.v[2].normal;
            if (glm::dot(face, vertexNormals) < 0.0) face = -face;
            const double faceLength = glm::length(face);
            placed.seedNormal = faceLength > 0.0 ? face / faceLength : glm::normalize(vertexNormals);
        }
        queue_.push_back(placed);
    }

    // Gathers the queued triangles (with `allowed`, only at the cells it marks); LimitError past a limit.
    void gather(const std::vector<uint8_t>* allowed) {
        const uint64_t maxCells = limits_.maxConstrainedCells;
        forTwoSlabs(box_.size.z, kMinimumSlices, [&](int32_t z0, int32_t) {
            (z0 == 0 ? *lower_ : *upper_).gather(queue_, seedValue_, allowed, maxCells);
        });
        queue_.clear();
        inputs_.clear();
        if (size() > maxCells)
            throw LimitError("cells hit by curve and input triangles", maxCells + 1, maxCells);
        if (testsPast_) throw LimitError("triangle/cell overlap tests", testsPast_, limits_.maxCellTests);
    }

    // An input triangle: its face normal at every vertex (none for a degenerate one, which then
    // only adds parameters), the inputs' parameters and material, a seed. Kept until the next gather.
    void addInput(const std::array<glm::dvec3, 3>& p, const InputOptions& options) {
        const glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(face);
        const glm::dvec3 normal = length > 0.0 ? face / length : glm::dvec3(0.0);
        RibbonTriangle& tri = inputs_.emplace_back();
        for (int i = 0; i < 3; ++i) tri.v[i] = {p[size_t(i)], normal, options.amplitude, options.roughness};
        tri.material = options.material;
        tri.seed = true;
        add(tri);
    }

    // Marks every cell within Chebyshev distance `radius` of a gathered cell as not allowed.
    void closeAround(std::vector<uint8_t>& allowed, int32_t radius) const {
        std::vector<uint8_t> near(box_.cellCount(), 0);
        for (const std::optional<GatheredSlab>* slab : {&lower_, &upper_})
            if (*slab)
                for (size_t cell : (*slab)->cells()) near[cell] = 1;
        // A Chebyshev ball is a cube: dilate along x, then y, then z.
        std::vector<uint8_t> line;
        for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            const int32_t n = box_.size[a];
            line.resize(size_t(n));
            for (int32_t j = 0; j < box_.size[c]; ++j)
                for (int32_t i = 0; i < box_.size[b]; ++i) {
                    glm::ivec3 q(0);
                    q[b] = i, q[c] = j;
                    auto at = [&](int32_t t) {
                        q[a] = t;
                        return box_.index(q.x, q.y, q.z);
                    };
                    for (int32_t t = 0; t < n; ++t) line[size_t(t)] = near[at(t)];
                    int64_t last = -int64_t(radius) - 1; // the nearest marked cell before t, forward
                    for (int32_t t = 0; t < n; ++t) {
                        if (line[size_t(t)]) last = t;
                        if (t - last <= radius) near[at(t)] = 1;
                    }
                    last = int64_t(n) + radius + 1;
                    for (int32_t t = n - 1; t >= 0; --t) {
                        if (line[size_t(t)]) last = t;
                        if (last - t <= radius) near[at(t)] = 1;
                    }
                }
        }
        for (size_t i = 0; i < near.size(); ++i)
            if (near[i]) allowed[i] = 0;
    }

    // Writes every gathered cell's values, both slabs side by side.
    // Every gathered cell's values: the lower slab's cells, then the upper's.
    GatheredConstraints result() const {
        GatheredConstraints out;
        out.box = box_;
        out.cells.reserve(size());
        for (const std::optional<GatheredSlab>* slab : {&lower_, &upper_})
            if (*slab) writeSlab(**slab, out);
        return out;
    }

private:
    // Boxes this thin are gathered on the calling thread alone.
    static constexpr int32_t kMinimumSlices = 16;

    size_t size() const { return lower_->size() + (upper_ ? upper_->size() : 0); }

    static void writeSlab(const GatheredSlab& slab, GatheredConstraints& out) {
        for (size_t i = 0; i < slab.size(); ++i) {
            const Gather& g = slab.gather(i);
            GatheredConstraints::Cell cell;
            cell.index = slab.cells()[i];
            const double length = glm::length(g.normal);
            cell.flags = kInParams;
            // A cell whose gathered normals cancel has no direction: it constrains neither N nor S.
            if (length >= 1e-6) {
                cell.flags |= kInNormals;
                const glm::dvec3 n = g.normal / length;
                cell.normal = glm::vec3(float(n.x), float(n.y), float(n.z));
                if (g.seeds > 0) {
                    cell.flags |= kInSurface;
                    cell.surface = float(g.surface / g.seeds);
                }
            }
            cell.amplitude = float(g.amplitude / g.count);
            cell.roughness = float(g.roughness / g.count);
            cell.material = slab.mostCounted(g);
            out.cells.push_back(cell);
        }
    }

    const Box& box_;
    SeedValue seedValue_;
    const Limits& limits_;
    uint64_t tests_ = 0, testsPast_ = 0;
    std::vector<PlacedTriangle> queue_;
    std::deque<RibbonTriangle> inputs_; // the input triangles queued (a deque keeps their addresses)
    std::optional<GatheredSlab> lower_, upper_; // the slices below the box's middle z and the rest (none for one slice)
};

} // namespace

GatheredConstraints gatherConstraints(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue,
                                      const Limits& limits, const std::vector<std::shared_ptr<const InputSurface>>& inputs,
                                      const InputOptions& inputOptions) {
    checkBox(box, limits);
    if (curves.size() > limits.maxCurves) throw LimitError("curves", curves.size(), limits.maxCurves);
    Gatherer gatherer(box, seedValue, limits);
    uint64_t segments = 0;
    for (size_t c = 0; c < curves.size(); ++c) {
        // Sampled in box-local coordinates: the result depends only on positions relative to the
        // box (an integer shift of curves and box changes nothing), with full precision near it.
        const std::string name = fmt::format("curve {}", c);
        validateCurve(curves[c], limits, name);
        FeatureCurve local = curves[c];
        for (glm::dvec3& p : local.points) p -= glm::dvec3(box.min);
        Limits localLimits = limits;
        localLimits.maxCoordinate = 2.0 * limits.maxCoordinate; // |point| and |box min| each within the limit
        const auto samples = sampleCurve(local, localLimits, name);
        segments += samples.size() - 1;
        if (segments > limits.maxSegments) throw LimitError("segments over all curves", segments, limits.maxSegments);
        const std::vector<RibbonTriangle> triangles = ribbonTriangles(samples, curves[c].seed);
        for (const RibbonTriangle& tri : triangles) gatherer.add(tri);
        gatherer.gather(nullptr);
    }
    if (!inputs.empty()) {
        // Becher et al.'s priorities: meshes gather only away from the curves' cells, heightmaps
        // only away from both; inputs of one kind gather together, in the order given.
        std::vector<uint8_t> allowed(box.cellCount(), 1);
        for (const InputSurface::Kind kind : {InputSurface::Kind::Mesh, InputSurface::Kind::Heightmap}) {
            if (std::none_of(inputs.begin(), inputs.end(), [&](const auto& input) { return input->kind == kind; }))
                continue;
            gatherer.closeAround(allowed, inputOptions.deadZone);
            for (const std::shared_ptr<const InputSurface>& input : inputs) {
                if (input->kind != kind) continue;
                for (const std::array<glm::dvec3, 3>& tri : input->triangles) gatherer.addInput(tri, inputOptions);
                gatherer.gather(&allowed);
                if (input->heights.empty()) continue;
                const size_t row = size_t(box.size.x) + 2;
                if (input->heights.size() != row * (size_t(box.size.z) + 2))
                    throw ParameterError(fmt::format("heightmap '{}' heights", input->name), double(input->heights.size()),
                                         "must cover the box's columns and one more on every side");
                auto vertex = [&](int32_t x, int32_t z) {
                    return glm::dvec3(x, input->heights[size_t(z + 1) * row + size_t(x + 1)], z);
                };
                // Two triangles a quad, (a, c, b) and (b, c, d), both facing +y.
                for (int32_t z = -1; z < box.size.z; ++z)
                    for (int32_t x = -1; x < box.size.x; ++x) {
                        const glm::dvec3 a = vertex(x, z), b = vertex(x + 1, z), c = vertex(x, z + 1), d = vertex(x + 1, z + 1);
                        gatherer.addInput({a, c, b}, inputOptions);
                        gatherer.addInput({b, c, d}, inputOptions);
                    }
                gatherer.gather(&allowed);
            }
        }
    }

    return gatherer.result();
}

Constraints voxelize(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue, const Limits& limits,
                     const std::vector<std::shared_ptr<const InputSurface>>& inputs, const InputOptions& inputOptions) {
    checkBox(box, limits);
    const FieldHeapReuse reuse(box.cellCount()); // the eight fields from the heap in huge pages (HeapReuse.h)
    return Constraints(gatherConstraints(curves, box, seedValue, limits, inputs, inputOptions));
}

} // namespace voxc::curves

#include "voxc/generators/curves/Voxelize.h"

#include "HeapReuse.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace voxc::curves {

Constraints::Constraints(const Box& box_)
    : box(box_), flags(box_.cellCount(), 0), normalX(box_), normalY(box_), normalZ(box_), amplitude(box_),
      roughness(box_), material(box_.cellCount(), 0), surface(box_) {}

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

struct Gather {
    glm::dvec3 normal{0.0};
    double amplitude = 0.0, roughness = 0.0, surface = 0.0;
    uint32_t count = 0, seeds = 0;
    bool guidanceOnly = true;
    std::map<uint16_t, uint32_t> materials;
};

// Range of cells whose cube can meet [lo, hi] (box-local) on one axis, clamped to the box (empty: first > last).
std::pair<int64_t, int64_t> cellRange(double lo, double hi, int32_t size) {
    const int64_t first = std::max<int64_t>(0, int64_t(std::ceil(lo - 0.5)));
    const int64_t last = std::min<int64_t>(size - 1, int64_t(std::floor(hi + 0.5)));
    return {first, last};
}

// Gathers triangles into their cells in the order given, counting the overlap tests against
// Limits::maxCellTests; with `allowed`, only at the cells it marks.
class Gatherer {
public:
    Gatherer(const Box& box, SeedValue seedValue, const Limits& limits)
        : box_(box), seedValue_(seedValue), limits_(limits) {}

    void add(const RibbonTriangle& tri, const std::vector<uint8_t>* allowed) {
        const std::array<glm::dvec3, 3> p = {tri.v[0].position, tri.v[1].position, tri.v[2].position};
        const glm::dvec3 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
        std::pair<int64_t, int64_t> range[3];
        uint64_t count = 1;
        for (int a = 0; a < 3; ++a) {
            range[a] = cellRange(lo[a], hi[a], box_.size[a]);
            count *= uint64_t(std::max<int64_t>(0, range[a].second - range[a].first + 1));
        }
        tests_ += count;
        if (tests_ > limits_.maxCellTests) throw LimitError("triangle/cell overlap tests", tests_, limits_.maxCellTests);
        if (count == 0) return;
        glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const glm::dvec3 vertexNormals = tri.v[0].normal + tri.v[1].normal + tri.v[2].normal;
        if (glm::dot(face, vertexNormals) < 0.0) face = -face;
        const double faceLength = glm::length(face);
        for (int64_t z = range[2].first; z <= range[2].second; ++z)
            for (int64_t y = range[1].first; y <= range[1].second; ++y)
                for (int64_t x = range[0].first; x <= range[0].second; ++x) {
                    const glm::dvec3 centre{double(x), double(y), double(z)};
                    const size_t index = box_.index(int32_t(x), int32_t(y), int32_t(z));
                    if (allowed && !(*allowed)[index]) continue;
                    if (!triangleOverlapsCube(p, centre, 1.0)) continue;
                    Gather& g = cells_[index];
                    if (cells_.size() > limits_.maxConstrainedCells)
                        throw LimitError("cells hit by curve and input triangles", cells_.size(),
                                         limits_.maxConstrainedCells);
                    const glm::dvec3 w = closestBarycentric(p, centre);
                    g.normal += w[0] * tri.v[0].normal + w[1] * tri.v[1].normal + w[2] * tri.v[2].normal;
                    g.amplitude += w[0] * tri.v[0].amplitude + w[1] * tri.v[1].amplitude + w[2] * tri.v[2].amplitude;
                    g.roughness += w[0] * tri.v[0].roughness + w[1] * tri.v[1].roughness + w[2] * tri.v[2].roughness;
                    ++g.count;
                    ++g.materials[tri.material];
                    if (tri.seed) {
                        const glm::dvec3 n = faceLength > 0.0 ? face / faceLength : glm::normalize(vertexNormals);
                        g.surface += seedValue_ == SeedValue::Zero ? 0.0 : glm::dot(n, centre - p[0]);
                        ++g.seeds;
                    }
                }
    }

    // An input triangle: its face normal at every vertex (none for a degenerate one, which then
    // only adds parameters), the inputs' parameters and material, a seed.
    void addInput(const std::array<glm::dvec3, 3>& p, const InputOptions& options, const std::vector<uint8_t>& allowed) {
        const glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(face);
        const glm::dvec3 normal = length > 0.0 ? face / length : glm::dvec3(0.0);
        RibbonTriangle tri;
        for (int i = 0; i < 3; ++i) tri.v[i] = {p[size_t(i)], normal, options.amplitude, options.roughness};
        tri.material = options.material;
        tri.seed = true;
        add(tri, &allowed);
    }

    // Marks every cell within Chebyshev distance `radius` of a gathered cell as not allowed.
    void closeAround(std::vector<uint8_t>& allowed, int32_t radius) const {
        std::vector<uint8_t> near(box_.cellCount(), 0);
        for (const auto& entry : cells_) near[entry.first] = 1;
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

    const std::map<size_t, Gather>& cells() const { return cells_; }

private:
    const Box& box_;
    SeedValue seedValue_;
    const Limits& limits_;
    uint64_t tests_ = 0;
    std::map<size_t, Gather> cells_; // ordered by cell index; each cell gathers in triangle order
};

} // namespace

Constraints voxelize(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue, const Limits& limits,
                     const std::vector<std::shared_ptr<const InputSurface>>& inputs, const InputOptions& inputOptions) {
    checkBox(box, limits);
    // The constraints' eight fields (27 bytes per box cell) come from the heap in huge pages, as
    // a solve's fields do (HeapReuse.h).
    const FieldHeapReuse reuse(box.cellCount());
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
        for (const RibbonTriangle& tri : ribbonTriangles(samples, curves[c].seed)) gatherer.add(tri, nullptr);
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
                for (const std::array<glm::dvec3, 3>& tri : input->triangles) gatherer.addInput(tri, inputOptions, allowed);
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
                        gatherer.addInput({a, c, b}, inputOptions, allowed);
                        gatherer.addInput({b, c, d}, inputOptions, allowed);
                    }
            }
        }
    }

    Constraints out(box);
    for (const auto& [index, g] : gatherer.cells()) {
        const double length = glm::length(g.normal);
        uint8_t flags = kInParams;
        // A cell whose gathered normals cancel has no direction: it constrains neither N nor S.
        if (length >= 1e-6) {
            flags |= kInNormals;
            const glm::dvec3 n = g.normal / length;
            out.normalX.values[index] = float(n.x);
            out.normalY.values[index] = float(n.y);
            out.normalZ.values[index] = float(n.z);
            if (g.seeds > 0) {
                flags |= kInSurface;
                out.surface.values[index] = float(g.surface / g.seeds);
            }
        }
        out.amplitude.values[index] = float(g.amplitude / g.count);
        out.roughness.values[index] = float(g.roughness / g.count);
        uint16_t best = 0;
        uint32_t bestCount = 0;
        for (const auto& [m, n] : g.materials) // ascending ids: ties keep the lowest
            if (n > bestCount) best = m, bestCount = n;
        out.material[index] = best;
        out.flags[index] = flags;
    }
    return out;
}

} // namespace voxc::curves

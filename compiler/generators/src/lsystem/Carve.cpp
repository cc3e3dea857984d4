#include "voxc/generators/lsystem/Carve.h"

#include "../FieldBuilder.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/Errors.h"
#include "voxc/program/FieldDag.h"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <set>
#include <tuple>

namespace voxc::lsystem {

namespace {

// The builtins' substream(seed, stream): seed + stream * golden ratio (as Connect.cpp).
uint32_t substream(uint32_t seed, uint32_t stream) { return seed + stream * 0x9E3779B9u; }

// Seed streams of spec §5.2.
constexpr uint32_t kCurlStream = 311, kCentreModulatorStream = 321, kSimplexModulatorStream = 322,
                   kVoronoiModulatorStream = 323, kSimplexStream = 331, kVoronoiStream = 341;

// Beyond r_clear the clearance term falls this many times faster than inside, so it reaches 0
// (rock) at 1.125 r_clear instead of 2 r_clear and leaves the rock around a tunnel to the brush.
constexpr double kClearanceFalloff = 8.0;

Value evalBuiltin(std::string_view name, glm::vec3 p, uint32_t seed) {
    const FunctionInfo* info = findFunction(name);
    VOXC_ASSERT(info != nullptr);
    const std::array<Value, 2> args{Value::makeVec3(p), Value::makeInt(int32_t(seed))};
    return info->eval(args);
}

void requireRange(const char* key, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi))
        throw UserError(fmt::format("lsystem_cave: '{}' is {}, outside [{}, {}]", key, value, lo, hi));
}

// The carve's nodes beyond the generators' common ones.
class CarveDag : public generators::FieldBuilder {
public:
    uint32_t pointSet(std::shared_ptr<const PointSet> set, uint32_t position) {
        FieldNode node;
        node.kind = FieldNode::Kind::PointSet;
        node.type = Type::Vec2;
        node.operands = {position};
        node.pointSet = std::move(set);
        return add(node);
    }
    // 0.5 + 0.5 simplex3(p * frequency, seed): a modulator in [0, 1].
    uint32_t modulator(uint32_t p, double frequency, uint32_t seedValue) {
        const uint32_t noise = call("simplex3", {call("mul", {p, number(frequency)}), seed(seedValue)});
        return call("add", {number(0.5), call("mul", {number(0.5), noise})});
    }
};

PointSetSegment floatSegment(glm::dvec3 a, glm::dvec3 b) {
    PointSetSegment s;
    s.from = glm::vec3(a);
    s.delta = glm::vec3(b - a);
    const float length2 = glm::dot(s.delta, s.delta);
    s.inverseLengthSquared = length2 > 0.0f ? 1.0f / length2 : 0.0f;
    return s;
}

// Calls `visit(a, b, type)` for every skeleton segment, then every connection-line segment (a
// tunnel).
template <typename Visit>
void forEachSegment(const Skeleton& skeleton, Visit visit) {
    for (const Segment& s : skeleton.segments) visit(s.from, s.to, s.type);
    for (const Connection& line : skeleton.connections)
        for (size_t k = 0; k + 1 < line.points.size(); ++k) visit(line.points[k], line.points[k + 1], SymbolType::Tunnel);
}

} // namespace

double centreReach(const CarveParams& params) { return 2.2 / params.minScale; }

double CarveParams::radiusOf(SymbolType type) const {
    return type == SymbolType::Room && roomRadius > 0 ? roomRadius : radius;
}
double segmentReach(const CarveParams& params) { return 1.25 * params.clearance; }

void checkCarveParams(const CarveParams& params) {
    requireRange("radius", params.radius, 0.5, 256);
    requireRange("room_radius", params.roomRadius, 0, 256);
    if (params.roomRadius != 0) requireRange("room_radius", params.roomRadius, 0.5, 256);
    requireRange("spacing", params.spacing, 0, 256);
    if (params.spacing != 0) requireRange("spacing", params.spacing, 0.25, 256);
    requireRange("clearance", params.clearance, 0.5, 256);
    requireRange("curl_amplitude", params.curlAmplitude, 0, 256);
    requireRange("curl_frequency", params.curlFrequency, 0, 16);
    requireRange("y_limit", params.yLimit, 0, 1);
    requireRange("simplex_frequency", params.simplexFrequency, 0, 16);
    requireRange("simplex_amplitude", params.simplexAmplitude, 0, 16);
    requireRange("voronoi_frequency", params.voronoiFrequency, 0, 16);
    requireRange("voronoi_amplitude", params.voronoiAmplitude, 0, 16);
    requireRange("modulation_frequency", params.modulationFrequency, 0, 16);
    requireRange("min_scale", params.minScale, 0.05, 16);
    requireRange("max_scale", params.maxScale, params.minScale, 16);
}

std::vector<StructuralPoint> structuralPoints(const Skeleton& skeleton, const CarveParams& params,
                                              const CarveLimits& limits) {
    using Key = std::tuple<double, double, double>;
    const auto pointsOn = [&](glm::dvec3 a, glm::dvec3 b, SymbolType type) {
        const double spacing = params.spacing > 0 ? params.spacing : params.radiusOf(type);
        return std::max<uint64_t>(1, uint64_t(std::ceil(glm::length(b - a) / spacing)));
    };
    std::set<Key> starts;
    uint64_t count = 0;
    forEachSegment(skeleton, [&](glm::dvec3 a, glm::dvec3 b, SymbolType type) {
        starts.insert({a.x, a.y, a.z});
        count += pointsOn(a, b, type) + 1; // + a possible leaf
        if (count > limits.maxCentres)
            throw LimitError("maxCentres", count, limits.maxCentres,
                             "the carve's structural points (one per spacing along the skeleton and its connections, "
                             "plus the leaves) would number at least", "CarveLimits");
    });
    std::vector<StructuralPoint> points;
    points.reserve(size_t(count));
    forEachSegment(skeleton, [&](glm::dvec3 a, glm::dvec3 b, SymbolType type) {
        const uint64_t n = pointsOn(a, b, type);
        const double radius = params.radiusOf(type);
        for (uint64_t k = 0; k < n; ++k) points.push_back({a + (double(k) / double(n)) * (b - a), radius});
        if (!starts.count({b.x, b.y, b.z})) points.push_back({b, radius});
    });
    return points;
}

glm::dvec3 displacedCentre(glm::dvec3 point, const CarveParams& params, uint32_t seed) {
    const glm::dvec3 c(evalBuiltin("curl3", glm::vec3(point * params.curlFrequency), substream(seed, kCurlStream)).v);
    const glm::dvec3 u = c / std::max(glm::length(c), 1.0);
    const double m =
        0.5 + 0.5 * double(evalBuiltin("simplex3", glm::vec3(point * params.modulationFrequency),
                                       substream(seed, kCentreModulatorStream)).v.x);
    return point + params.curlAmplitude * m * glm::dvec3(u.x, params.yLimit * u.y, u.z);
}

PointBins binCarveCells(const PointSet& set, glm::ivec3 worldOrigin, glm::ivec3 worldSize, const CarveLimits& limits) {
    try {
        return binPointSetOverGrid(set, worldOrigin, worldSize, limits.maxListEntries, limits.maxPerCell);
    } catch (const PointSetLimitError& e) {
        if (std::string_view(e.limit) == "cellTests")
            throw LimitError("maxCellTests", e.amount, e.cap,
                             fmt::format("binning the carve's points would test this many (point, {}^3 cell) pairs "
                                         "(their bounding boxes; long segments or a large radius make many) at least",
                                         kPointSetCellSize), "CarveLimits");
        if (std::string_view(e.limit) == "cells")
            throw LimitError("kMaxPointSetCells", e.amount, e.cap,
                             fmt::format("the carve's lists cover the checked world in {}^3 cells (a world unbounded "
                                         "in x or z is as wide as 2^20 voxels); this many cells",
                                         kPointSetCellSize), "voxc/program/PointSet.h");
        if (std::string_view(e.limit) == "perCell")
            throw LimitError("maxPerCell", e.amount, e.cap,
                             fmt::format("one {}^3 cell would list this many centres or skeleton segments of the carve "
                                         "(the points whose reach meets it) at least",
                                         kPointSetCellSize), "CarveLimits");
        throw LimitError("maxListEntries", e.amount, e.cap,
                         "the carve's per-cell lists (with those of the lsystem_cave features before it) would hold "
                         "at least", "CarveLimits");
    }
}

std::shared_ptr<const PointSet> carvePointSet(const Skeleton& skeleton, const CarveParams& params, uint32_t seed,
                                              glm::ivec3 worldOrigin, glm::ivec3 worldSize, const CarveLimits& limits) {
    checkCarveParams(params);
    auto set = std::make_shared<PointSet>();
    for (const StructuralPoint& point : structuralPoints(skeleton, params, limits)) {
        set->centres.push_back(glm::vec3(displacedCentre(point.position, params, seed)));
        set->centreScales.push_back(float(1.0 / point.radius));
    }
    uint64_t segments = 0;
    forEachSegment(skeleton, [&](glm::dvec3, glm::dvec3, SymbolType) { ++segments; });
    if (segments > limits.maxClearanceSegments)
        throw LimitError("maxClearanceSegments", segments, limits.maxClearanceSegments,
                         "the carve's clearance segments (skeleton and connection lines) would number", "CarveLimits");
    set->segments.reserve(size_t(segments));
    forEachSegment(skeleton,
                   [&](glm::dvec3 a, glm::dvec3 b, SymbolType) { set->segments.push_back(floatSegment(a, b)); });
    set->centreReach = float(centreReach(params));
    set->segmentReach = float(segmentReach(params));
    set->clearance = float(params.clearance);
    set->bins = binCarveCells(*set, worldOrigin, worldSize, limits);
    return set;
}

Field carveField(std::shared_ptr<const PointSet> set, const CarveParams& params, uint32_t seed, CarveFrame frame) {
    CarveDag dag;
    const uint32_t p = dag.worldPosition();
    const uint32_t distances = dag.pointSet(std::move(set), frame == CarveFrame::Stamp ? dag.position() : p);
    const uint32_t centreDistance = dag.component(distances, 0), skeletonDistance = dag.component(distances, 1);

    // M(v): one simplex, three worley F1 octaves, two modulators.
    const uint32_t simplex = dag.call(
        "simplex3", {dag.call("mul", {p, dag.number(params.simplexFrequency)}), dag.seed(substream(seed, kSimplexStream))});
    uint32_t voronoi = 0;
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t f1 = dag.call("worley_f1", {dag.call("mul", {p, dag.number(params.voronoiFrequency * double(1u << k))}),
                                                   dag.seed(substream(seed, kVoronoiStream + k))});
        const uint32_t octave = dag.call("sub", {dag.call("mul", {dag.number(2.0), dag.call("min", {f1, dag.number(1.0)})}),
                                                 dag.number(1.0)});
        const uint32_t weighted = k == 0 ? octave : dag.call("mul", {octave, dag.number(1.0 / double(1u << k))});
        voronoi = k == 0 ? weighted : dag.call("add", {voronoi, weighted});
    }
    voronoi = dag.call("mul", {voronoi, dag.number(1.0 / 1.75)});
    const uint32_t simplexWeight = dag.modulator(p, params.modulationFrequency, substream(seed, kSimplexModulatorStream));
    const uint32_t voronoiWeight = dag.modulator(p, params.modulationFrequency, substream(seed, kVoronoiModulatorStream));
    uint32_t scale = dag.call("add", {dag.number(1.0), dag.call("mul", {dag.call("mul", {dag.number(params.simplexAmplitude),
                                                                                         simplexWeight}),
                                                                        simplex})});
    scale = dag.call("add", {scale, dag.call("mul", {dag.call("mul", {dag.number(params.voronoiAmplitude), voronoiWeight}),
                                                    voronoi})});
    scale = dag.call("clamp", {scale, dag.number(params.minScale), dag.number(params.maxScale)});

    // f = max(clamp(1 - M D / 2, 0, 1), min(0.5 + 0.5x, 0.5 + 4x)), x = 1 - D_s / r_clear, D the
    // least |v - c_i| / R_i (the point set's scaled distance): the
    // spec's (1 + max(F, F_clr)) / 2 written so that beyond the reaches both terms pass an exact 0
    // through clamp and max, which interval analysis then proves constant.
    const uint32_t brush = dag.call(
        "clamp", {dag.call("sub", {dag.number(1.0), dag.call("mul", {dag.call("mul", {scale, centreDistance}),
                                                                    dag.number(0.5)})}),
                  dag.number(0.0), dag.number(1.0)});
    const uint32_t x = dag.call(
        "sub", {dag.number(1.0), dag.call("mul", {skeletonDistance, dag.number(1.0 / params.clearance)})});
    const uint32_t inside = dag.call("add", {dag.number(0.5), dag.call("mul", {x, dag.number(0.5)})});
    const uint32_t outside = dag.call("add", {dag.number(0.5), dag.call("mul", {x, dag.number(0.5 * kClearanceFalloff)})});
    const uint32_t clearance = dag.call("min", {inside, outside});
    return dag.field(dag.call("max", {brush, clearance}));
}

} // namespace voxc::lsystem

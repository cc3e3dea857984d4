#include "voxc/generators/lsystem/Connect.h"

#include "voxc/builtins/Functions.h"
#include "voxc/generators/lsystem/Selection.h"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>

namespace voxc::lsystem {

namespace {

// The curl field's seed: the builtins' substream(seed, 301) (seed + stream * golden ratio).
uint32_t curlSeed(uint32_t seed) { return seed + 301u * 0x9E3779B9u; }

// c / max(|c|, 1) of the builtin curl3 at p * frequency: a direction of length at most 1.
glm::dvec3 curlDirection(glm::dvec3 p, double frequency, uint32_t seed) {
    static const FunctionInfo* curl3 = findFunction("curl3");
    VOXC_ASSERT(curl3 != nullptr);
    const std::array<Value, 2> args{Value::makeVec3(glm::vec3(p * frequency)), Value::makeInt(int32_t(curlSeed(seed)))};
    const glm::dvec3 c(curl3->eval(args).v);
    return c / std::max(glm::length(c), 1.0);
}

void checkRange(const char* key, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi))
        throw UserError(fmt::format("connect: '{}' is {}, outside [{}, {}]", key, value, lo, hi));
}

class Connector {
public:
    Connector(Skeleton& skeleton, const ConnectParams& params, uint32_t seed, const Limits& limits)
        : skeleton_(skeleton), params_(params), seed_(seed), limits_(limits), used_(skeleton.segments.size()) {}

    void run() {
        const auto& endpoints = skeleton_.endpoints;
        std::vector<uint32_t> order(endpoints.size());
        for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        for (size_t k = order.size(); k > 1; --k) // Fisher-Yates
            std::swap(order[k - 1], order[uniformIndex({seed_, Stream::ConnectShuffle, 0, uint32_t(k - 1), 0}, uint32_t(k))]);
        std::optional<uint32_t> start;
        for (uint32_t k = 0; k < order.size(); ++k) {
            const uint32_t e = order[k];
            if (uniform({seed_, Stream::ConnectChance, 0, k, 0}) >= params_.chance) continue; // stays a dead end
            if (!start) start = e;
            else if (distance(*start, e) > params_.maxDistance) start = e; // the old start is discarded
            else connect(*start, e), start.reset();
        }
        // "Eliminate the dead ends completely" (L989) even with an odd count: the leftover start
        // joins its nearest endpoint within reach.
        if (start && params_.chance >= 1) {
            std::optional<uint32_t> nearest;
            for (uint32_t e = 0; e < endpoints.size(); ++e)
                if (e != *start && distance(*start, e) <= params_.maxDistance &&
                    (!nearest || distance(*start, e) < distance(*start, *nearest)))
                    nearest = e;
            if (nearest) connect(*start, *nearest);
        }
    }

private:
    double distance(uint32_t a, uint32_t b) const {
        return glm::length(skeleton_.endpoints[b].position - skeleton_.endpoints[a].position);
    }

    void connect(uint32_t from, uint32_t to) {
        const glm::dvec3 a = skeleton_.endpoints[from].position, b = skeleton_.endpoints[to].position;
        const uint64_t n = std::max<uint64_t>(1, uint64_t(std::ceil(glm::length(b - a) / params_.spacing)));
        if (used_ + n > limits_.maxSegments)
            throw LimitError("maxSegments", used_ + n, limits_.maxSegments,
                             "the skeleton and its connections would have this many segments");
        used_ += n;
        Connection line{from, to, {}};
        line.points.reserve(size_t(n + 1));
        line.points.push_back(a);
        for (uint64_t k = 1; k < n; ++k) {
            const double t = double(k) / double(n);
            const glm::dvec3 straight = a + t * (b - a);
            line.points.push_back(straight + params_.amplitude * std::sin(std::numbers::pi * t) *
                                                 curlDirection(straight, params_.frequency, seed_));
        }
        line.points.push_back(b);
        skeleton_.connections.push_back(std::move(line));
    }

    Skeleton& skeleton_;
    const ConnectParams& params_;
    uint32_t seed_;
    const Limits& limits_;
    uint64_t used_; // segments so far, connections included
};

} // namespace

void checkConnectParams(const ConnectParams& params) {
    checkRange("chance", params.chance, 0, 1);
    checkRange("max_distance", params.maxDistance, 0, 1e7);
    checkRange("frequency", params.frequency, 0, 1e3);
    checkRange("amplitude", params.amplitude, 0, 1e4);
    checkRange("spacing", params.spacing, 1e-3, 1e4);
}

void connectBranches(Skeleton& skeleton, const ConnectParams& params, uint32_t seed, const Limits& limits) {
    checkConnectParams(params);
    Connector(skeleton, params, seed, limits).run();
}

} // namespace voxc::lsystem

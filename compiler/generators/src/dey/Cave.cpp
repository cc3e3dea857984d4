// Cave (Dey Eq 4.3): a particle traced from `start` along `direction`, pulled down by gravity
// and pushed by curl noise, carving a sphere whose radius decays; the field is 1 inside the
// swept spheres, so `subtract` carves it. docs/language.md ("Features").
#include "Placement.h"
#include "Records.h"

#include "voxc/builtins/Functions.h"

#include <array>
#include <cmath>

namespace voxc::dey {

namespace {

using K = GeneratorKeyType;

// Curl noise is sampled at the particle position times this (cycles per voxel).
constexpr double kCurlFrequency = 0.1;

// Table 4.3 (ranges, steps) and Table 4.6 (defaults).
constexpr GeneratorKey kKeys[] = {
    {"start", K::Vec3, -1e6, 1e6, 0, {16, 16, 4}},
    {"direction", K::Vec3, -1, 1, 0, {0, 0, 1}},
    {"iterations", K::Integer, 10, 50, 10, {20, 0, 0}},
    {"mouth", K::Number, 1, 10, 0.2, {5, 0, 0}},
    {"curl", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"decay", K::Number, 0, 1, 0.01, {0, 0, 0}},
    {"gravity", K::Number, 0, 1, 0.01, {1, 0, 0}},
    {"gravity_exponent", K::Number, 1, 4, 0.02, {1, 0, 0}},
    kTranslateKey,
    kRotateKey,
};

std::optional<GeneratorProblem> validate(const GeneratorParams& params) {
    if (params.vec("direction") == glm::dvec3(0.0))
        return GeneratorProblem{"direction", "a cave's 'direction' must not be [0, 0, 0]"};
    return std::nullopt;
}

glm::dvec3 curl(glm::dvec3 position, uint32_t seed) {
    static const FunctionInfo* curl3 = findFunction("curl3");
    const std::array<Value, 2> args{Value::makeVec3(glm::vec3(position * kCurlFrequency)), Value::makeInt(int32_t(seed))};
    return glm::dvec3(curl3->eval(args).v);
}

Field build(const GeneratorParams& params, uint32_t seed) {
    const glm::dvec3 start = params.vec("start");
    const glm::dvec3 direction = glm::normalize(params.vec("direction"));
    const int steps = int(params.number("iterations"));
    const double mouth = params.number("mouth"), decay = params.number("decay");
    const double gravity = params.number("gravity"), gravityExponent = params.number("gravity_exponent");
    const double curlScale = params.number("curl");

    std::vector<glm::dvec3> points{start};
    std::vector<double> radii{mouth};
    glm::dvec3 position = start;
    for (int t = 0; t < steps; ++t) {
        const glm::dvec3 fall(0.0, -gravity * std::pow(double(t) / steps, gravityExponent), 0.0);
        position += direction + fall + curlScale * curl(position, seed);
        const double radius = std::max(0.0, mouth - (t + 1) * decay * mouth / steps);
        points.push_back(position);
        radii.push_back(radius);
        if (radius == 0.0) break;
    }
    const Placement placement = Placement::of(params, start);
    for (glm::dvec3& point : points) point = placement.apply(point);
    FieldBuilder builder;
    return builder.field(builder.call("density", {sweptSpheres(builder, points, radii), builder.number(1.0)}));
}

} // namespace

const GeneratorInfo& caveGenerator() {
    static const GeneratorInfo info{"cave", kKeys, validate, build};
    return info;
}

} // namespace voxc::dey

#include "voxc/builtins/Shapes.h"

#include "voxc/builtins/Ops.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc {

namespace {

constexpr double kCoord = 1.0e6; // bound on positions and sizes, far beyond any grid limit

glm::vec3 toVec3(const double* v) { return {float(v[0]), float(v[1]), float(v[2])}; }

std::string glslVec3(glm::vec3 v) {
    return fmt::format("vec3({}, {}, {})", glslFloat(v.x), glslFloat(v.y), glslFloat(v.z));
}

// Every shape writes `value` where it is solid.
constexpr KeySpec kValueKey{"value", KeyType::Number, false, -kCoord, kCoord,
                            [](StartShape& s, const double* v) { s.value = float(v[0]); }};

// Fill: every voxel.
const KeySpec kFillKeys[] = {kValueKey};

bool fillInside(const StartShape&, glm::ivec3, glm::ivec3, uint32_t) { return true; }

std::string fillGlsl(const StartShape&) { return "inside = true;"; }

// Box: min <= p < max, per axis.
const KeySpec kBoxKeys[] = {
    {"min", KeyType::Vec3, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.min = toVec3(v); }},
    {"max", KeyType::Vec3, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.max = toVec3(v); }},
    kValueKey,
};

bool boxInside(const StartShape& s, glm::ivec3 local, glm::ivec3, uint32_t) {
    const glm::vec3 p(local);
    return p.x >= s.min.x && p.y >= s.min.y && p.z >= s.min.z && p.x < s.max.x && p.y < s.max.y && p.z < s.max.z;
}

std::string boxGlsl(const StartShape& s) {
    return fmt::format("inside = all(greaterThanEqual(vec3(local), {})) && all(lessThan(vec3(local), {}));",
                       glslVec3(s.min), glslVec3(s.max));
}

// Sphere: |p - center|^2 <= radius^2 (squared, so no sqrt can differ between devices).
const KeySpec kSphereKeys[] = {
    {"center", KeyType::Vec3, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.center = toVec3(v); }},
    {"radius", KeyType::Number, true, 0.0, kCoord, [](StartShape& s, const double* v) { s.radius = float(v[0]); }},
    kValueKey,
};

bool sphereInside(const StartShape& s, glm::ivec3 local, glm::ivec3, uint32_t) {
    const glm::vec3 d = glm::vec3(local) - s.center;
    const float distanceSquared = d.x * d.x + d.y * d.y + d.z * d.z;
    return distanceSquared <= s.radius * s.radius;
}

std::string sphereGlsl(const StartShape& s) {
    return fmt::format("precise vec3 d = vec3(local) - {};\n"
                       "precise float distanceSquared = d.x * d.x + d.y * d.y + d.z * d.z;\n"
                       "inside = distanceSquared <= {};",
                       glslVec3(s.center), glslFloat(s.radius * s.radius));
}

// Wall: at <= p[axis] < at + thickness.
const KeySpec kWallKeys[] = {
    {"axis", KeyType::Axis, true, 0.0, 2.0, [](StartShape& s, const double* v) { s.axis = int32_t(v[0]); }},
    {"at", KeyType::Number, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.at = float(v[0]); }},
    {"thickness", KeyType::Number, false, 0.0, kCoord,
     [](StartShape& s, const double* v) { s.thickness = float(v[0]); }},
    kValueKey,
};

bool wallInside(const StartShape& s, glm::ivec3 local, glm::ivec3, uint32_t) {
    const float p = float(local[s.axis]);
    return p >= s.at && p < s.at + s.thickness;
}

std::string wallGlsl(const StartShape& s) {
    const char axis = "xyz"[s.axis];
    return fmt::format("inside = float(local.{0}) >= {1} && float(local.{0}) < {2};", axis, glslFloat(s.at),
                       glslFloat(s.at + s.thickness));
}

// Half-space: dot(p, normal) <= offset.
const KeySpec kHalfSpaceKeys[] = {
    {"normal", KeyType::Vec3, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.normal = toVec3(v); }},
    {"offset", KeyType::Number, true, -kCoord, kCoord, [](StartShape& s, const double* v) { s.offset = float(v[0]); }},
    kValueKey,
};

bool halfSpaceInside(const StartShape& s, glm::ivec3 local, glm::ivec3, uint32_t) {
    const glm::vec3 p(local);
    const float d = p.x * s.normal.x + p.y * s.normal.y + p.z * s.normal.z;
    return d <= s.offset;
}

std::string halfSpaceGlsl(const StartShape& s) {
    return fmt::format("precise vec3 p = vec3(local) * {};\n"
                       "precise float d = p.x + p.y + p.z;\n"
                       "inside = d <= {};",
                       glslVec3(s.normal), glslFloat(s.offset));
}

// Heightfield: solid below a fractal Perlin surface sampled at world (x, z) (Dey §3.2).
const KeySpec kHeightfieldKeys[] = {
    {"base", KeyType::Number, false, -kCoord, kCoord,
     [](StartShape& s, const double* v) { s.heightfield.base = float(v[0]); }},
    {"amplitude", KeyType::Number, false, 0.0, kCoord,
     [](StartShape& s, const double* v) { s.heightfield.amplitude = float(v[0]); }},
    {"frequency", KeyType::Number, false, 0.0, 1.0,
     [](StartShape& s, const double* v) { s.heightfield.frequency = float(v[0]); }},
    {"octaves", KeyType::Integer, false, 1.0, 8.0,
     [](StartShape& s, const double* v) { s.heightfield.octaves = int32_t(v[0]); }},
    {"lacunarity", KeyType::Number, false, 1.0, 4.0,
     [](StartShape& s, const double* v) { s.heightfield.lacunarity = float(v[0]); }},
    {"gain", KeyType::Number, false, 0.0, 1.0, [](StartShape& s, const double* v) { s.heightfield.gain = float(v[0]); }},
    kValueKey,
};

bool heightfieldInside(const StartShape& s, glm::ivec3 local, glm::ivec3 world, uint32_t seed) {
    return float(local.y) < heightfieldHeight(s.heightfield, seed, world.x, world.z);
}

std::string heightfieldGlsl(const StartShape&) { return "inside = float(local.y) < column;"; }

std::string heightfieldColumnGlsl(const StartShape& s) {
    const HeightfieldParams& h = s.heightfield;
    return fmt::format("heightfieldHeight(world.x, world.z, seed, {}, {}, {}, {}, {}, {})", glslFloat(h.base),
                       glslFloat(h.amplitude), glslFloat(h.frequency), h.octaves, glslFloat(h.lacunarity),
                       glslFloat(h.gain));
}

const ShapeInfo kShapes[] = {
    {ShapeKind::Fill, "fill", kFillKeys, fillInside, fillGlsl},
    {ShapeKind::Box, "box", kBoxKeys, boxInside, boxGlsl},
    {ShapeKind::Sphere, "sphere", kSphereKeys, sphereInside, sphereGlsl},
    {ShapeKind::Wall, "wall", kWallKeys, wallInside, wallGlsl},
    {ShapeKind::HalfSpace, "halfspace", kHalfSpaceKeys, halfSpaceInside, halfSpaceGlsl},
    {ShapeKind::Heightfield, "heightfield", kHeightfieldKeys, heightfieldInside, heightfieldGlsl, heightfieldColumnGlsl},
};

} // namespace

std::span<const ShapeInfo> shapes() { return kShapes; }

const ShapeInfo& shapeInfo(ShapeKind kind) {
    for (const ShapeInfo& info : kShapes)
        if (info.kind == kind) return info;
    throw InternalError("unknown start shape");
}

std::optional<ShapeKind> findShape(std::string_view name) {
    for (const ShapeInfo& info : kShapes)
        if (info.name == name) return info.kind;
    return std::nullopt;
}

VoxelState startVoxel(const Program& program, glm::ivec3 local) {
    const glm::ivec3 world = program.world.origin + local;
    VoxelState voxel;
    for (const StartShape& shape : program.start) {
        if (!shapeInfo(shape.kind).inside(shape, program.world.localBase + local, world, program.world.seed)) continue;
        voxel.density = shape.value;
        if (shape.material) voxel.material = *shape.material;
    }
    return voxel;
}

} // namespace voxc

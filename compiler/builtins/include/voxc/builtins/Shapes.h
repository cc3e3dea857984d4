#pragma once
// The start block's shapes, one registry record each: the keys the checker accepts (type,
// range, default), the interpreter's evaluation and the GLSL emission side by side.
#include "voxc/program/Program.h"
#include "voxc/program/Semantics.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxc {

enum class KeyType : uint8_t { Number, Integer, Vec3, Axis };

struct KeySpec {
    std::string_view name;
    KeyType type;
    bool required;
    double min; // inclusive bounds on a Number/Integer, or on each Vec3 component
    double max;
    // Stores the checked value; Axis arrives as 0, 1 or 2, Number/Integer as values[0].
    void (*set)(StartShape& shape, const double* values);
};

struct ShapeInfo {
    ShapeKind kind;
    std::string_view name;
    std::span<const KeySpec> keys;
    // Whether the shape is solid at one voxel; there it writes its value (and material).
    bool (*inside)(const StartShape& shape, glm::ivec3 local, glm::ivec3 world, uint32_t seed);
    // GLSL statements that set `bool inside` from `ivec3 local`, `ivec3 world` and `uint seed`
    // (and `float column`, see below), as `inside` computes it.
    std::string (*glsl)(const StartShape& shape);
    // Optional: a GLSL float expression of `world.x`, `world.z` and `seed` only, which the start
    // kernel evaluates once per (x, z) column and hands to `glsl` as `column` (a heightfield's
    // surface height). nullptr when the shape has none.
    std::string (*columnGlsl)(const StartShape& shape) = nullptr;
};

std::span<const ShapeInfo> shapes();
const ShapeInfo& shapeInfo(ShapeKind kind);
std::optional<ShapeKind> findShape(std::string_view name);

// The start state at one voxel: every shape in order over air (density 0, material none); a
// shape writes its value, and its material if it has one, where it is inside.
VoxelState startVoxel(const Program& program, glm::ivec3 local);

// 2D improved Perlin noise with Perlin's reference permutation, range about [-1, 1].
// compiler/shaders/perlin.glsl mirrors it; both avoid fused multiply-adds so they agree bit for bit.
float perlin2(float x, float y);
// Ken Perlin's reference permutation, the one table perlin2 uses. The Vulkan runtime uploads it
// to the kernels' noise-table buffer (kBindingNoiseTables), so the GPU reads the same table.
std::span<const int, 256> perlinPermutation();
// The heightfield's surface height at world column (x, z).
float heightfieldHeight(const HeightfieldParams& params, uint32_t seed, int worldX, int worldZ);

} // namespace voxc

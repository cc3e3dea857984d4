#pragma once
// A checked field expression: a typed DAG whose nodes are constants, position inputs and calls
// of builtin functions (compiler/builtins/include/voxc/builtins/Functions.h; arithmetic,
// comparisons and logic are builtins too, so every operation has one registry record).
// `let` bindings and user functions are resolved by the checker: a let is a shared node, a user
// function is inlined. Nodes are in topological order: every operand precedes its user.
#include "voxc/core/SourceLoc.h"
#include "voxc/program/PointSet.h"
#include "voxc/program/SampledMap.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

namespace voxc {

// The value types of field expressions.
enum class Type : uint8_t { Float, Int, Bool, Vec2, Vec3 };

// Position inputs. Grid-local voxel indices and world voxel coordinates (origin + local), as floats.
enum class FieldInput : uint8_t { LocalX, LocalY, LocalZ, WorldX, WorldY, WorldZ };

struct FieldNode {
    // PointSet: vec2 of the capped distances from the operand (a vec3 world position) to the
    // nearest centre and segment of `pointSet` (voxc/program/PointSet.h); features build it.
    // Map: the float `map` holds at world (x, z) = its two float operands (voxc/program/SampledMap.h).
    enum class Kind : uint8_t { Constant, Input, Call, Component, PointSet, Map };
    Kind kind = Kind::Constant;
    Type type = Type::Float;
    SourceLoc loc;
    glm::vec3 constant{0.0f};       // Constant of type Float (x) / Vec2 (xy) / Vec3
    int32_t constantInt = 0;        // Constant of type Int
    bool constantBool = false;      // Constant of type Bool
    FieldInput input = FieldInput::LocalX;
    uint32_t function = 0;          // Call: index into voxc::functions()
    uint32_t component = 0;         // Component: 0..2 of a vector operand (swizzles build vec2/vec3 via calls)
    std::vector<uint32_t> operands; // Call arguments / Component's vector / PointSet's position / Map's x, z
    std::shared_ptr<const PointSet> pointSet; // PointSet only; shared, never changed after checking
    std::shared_ptr<const SampledMap> map;    // Map only; shared, never changed after checking
};

struct Field {
    std::string name;
    SourceLoc loc;
    std::vector<FieldNode> nodes;
    uint32_t root = 0; // a Float node: the field's value at a voxel
};

} // namespace voxc

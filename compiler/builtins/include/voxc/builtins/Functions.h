#pragma once
// Builtin functions of field expressions (noise, fractals, warps; later SDFs and generators),
// one registry record each, godot_voxel style: the checker's type rule, the interpreter's
// evaluation, the GLSL emitter, the GLSL library it needs and the documented CPU/GPU tolerance
// side by side, so no backend can silently miss a function.
#include "voxc/program/Field.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxc {

std::string_view typeName(Type type); // "float", "int", "bool", "vec2", "vec3"

// A value of a field expression. Only the members of its type are meaningful.
struct Value {
    Type type = Type::Float;
    glm::vec3 v{0.0f}; // Float: v.x; Vec2: v.xy; Vec3: v
    int32_t i = 0;     // Int
    bool b = false;    // Bool

    static Value makeFloat(float x) { return {Type::Float, {x, 0.0f, 0.0f}, 0, false}; }
    static Value makeInt(int32_t x) { return {Type::Int, glm::vec3(0.0f), x, false}; }
    static Value makeBool(bool x) { return {Type::Bool, glm::vec3(0.0f), 0, x}; }
    static Value makeVec2(glm::vec2 x) { return {Type::Vec2, {x.x, x.y, 0.0f}, 0, false}; }
    static Value makeVec3(glm::vec3 x) { return {Type::Vec3, x, 0, false}; }
};

// The value of a Constant field node.
inline Value constantValue(const FieldNode& node) { return {node.type, node.constant, node.constantInt, node.constantBool}; }

struct FunctionInfo {
    std::string_view name;
    std::string_view signature; // for diagnostics and docs, e.g. "perlin3(p: vec3, seed: int) -> float"
    std::string_view doc;       // one line: what it computes, its range
    // The result type for these argument types, or nullopt when they do not fit (the checker
    // then reports E0010 quoting `signature`).
    std::optional<Type> (*typeRule)(std::span<const Type> args);
    Value (*eval)(std::span<const Value> args);
    // A GLSL expression computing the result from GLSL expressions for the arguments.
    std::string (*glsl)(std::span<const std::string> args, std::span<const Type> argTypes);
    // compiler/shaders files the emitted expression calls into (e.g. "noise_perlin.glsl"), in include order.
    std::span<const std::string_view> glslLibraries;
    // Largest absolute difference allowed between the interpreter and the GPU (0: bit-exact).
    float tolerance;
};

std::span<const FunctionInfo> functions();
const FunctionInfo* findFunction(std::string_view name);

} // namespace voxc

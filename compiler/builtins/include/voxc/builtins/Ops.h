#pragma once
// The grammar's operators, one registry record each (godot_voxel style): the record holds
// its arity for the checker, its set semantics for the checker's analyses, its interpreter
// evaluation and its GLSL emission side by side, so no backend can miss an operator.
#include "voxc/builtins/ValueSet.h"
#include "voxc/program/Program.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxc {

struct SymbolOpInfo {
    SymbolOp op;
    std::string_view name;
    bool takesValue;
    bool (*eval)(float density, float value);
    ValueSet (*accepts)(float value);
    // A GLSL bool expression; `density` and `value` are GLSL expressions.
    std::string (*glsl)(const std::string& density, const std::string& value);
    std::string_view doc; // one line for hover help (voxc lsp): when the cell passes
};

struct TransformOpInfo {
    TransformOp op;
    std::string_view name;
    bool takesValue;
    bool writes; // false for NOP: the cell is left untouched (and not clamped)
    float (*eval)(float density, float value);
    std::string (*glsl)(const std::string& density, const std::string& value);
    std::string_view doc; // one line for hover help (voxc lsp): what the cell writes
};

// Material tests (MAT m, NMAT m) in symbol cells. A transform cell's `MAT m` is not a record of
// its own: it always writes m (TransformCell::material).
struct MaterialOpInfo {
    MaterialOp op;
    std::string_view name;
    bool (*eval)(uint8_t material, uint8_t id);
    // A GLSL bool expression; `material` and `id` are GLSL uint expressions.
    std::string (*glsl)(const std::string& material, const std::string& id);
    std::string_view doc; // one line for hover help (voxc lsp)
};

std::span<const SymbolOpInfo> symbolOps();
std::span<const MaterialOpInfo> materialOps();
const MaterialOpInfo& materialOpInfo(MaterialOp op);
std::optional<MaterialOp> findMaterialOp(std::string_view name);
std::span<const TransformOpInfo> transformOps();
const SymbolOpInfo& symbolOpInfo(SymbolOp op);
const TransformOpInfo& transformOpInfo(TransformOp op);
std::optional<SymbolOp> findSymbolOp(std::string_view name);
std::optional<TransformOp> findTransformOp(std::string_view name);

// A GLSL float literal that parses back to exactly `v` (v must be finite).
std::string glslFloat(float v);

// Interpreter helpers built from the records.
bool cellPasses(const SymbolCell& cell, float density, uint8_t material);
// The value a transform cell writes, clamped to [clampMin, clampMax] where given; NOP returns density.
float applyTransform(const TransformCell& cell, float density, const Grammar& grammar);

} // namespace voxc

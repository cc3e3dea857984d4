// GLSL for a field stage: the field's DAG as straight-line SSA code (one variable per node,
// constants written inline), the per-column nodes before the y loop, then the combine of
// FieldMode written exactly as voxc::combineField computes it with std::min / std::max.
#include "voxc/codegen/KernelSources.h"
#include "Template.h"

#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/codegen/PointSets.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"
#include "voxc/program/Semantics.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace voxc::codegen {

namespace {

bool isFloatType(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3; }

std::string constantGlsl(const FieldNode& node) {
    const glm::vec3 c = node.constant;
    switch (node.type) {
    case Type::Float: return glslFloat(c.x);
    case Type::Int:
        // -2147483648 is not a GLSL literal (unary minus of an out-of-range int).
        return node.constantInt == INT32_MIN ? "(-2147483647 - 1)" : std::to_string(node.constantInt);
    case Type::Bool: return node.constantBool ? "true" : "false";
    case Type::Vec2: return fmt::format("vec2({}, {})", glslFloat(c.x), glslFloat(c.y));
    case Type::Vec3: return fmt::format("vec3({}, {}, {})", glslFloat(c.x), glslFloat(c.y), glslFloat(c.z));
    }
    return "?";
}

// x, y, z are the grid index plus World::localBase (0 but in a region grid), summed as integers.
std::string inputGlsl(FieldInput input, glm::ivec3 localBase) {
    const int axis = int(input) % 3;
    const bool world = input >= FieldInput::WorldX;
    const bool perColumn = axis != 1;
    const char* vector = world ? (perColumn ? "columnWorld" : "world") : (perColumn ? "columnLocal" : "local");
    if (!world && localBase[axis] != 0) return fmt::format("float({}.{} + ({}))", vector, "xyz"[axis], localBase[axis]);
    return fmt::format("float({}.{})", vector, "xyz"[axis]);
}

// Declares binding kBindingPointSets and pointSetDistances.
constexpr std::string_view kPointSetLibrary = "lsystem_carve.glsl";

// Each node's GLSL: a variable name, or the literal of a constant.
struct FieldCode {
    std::vector<std::string> names;
    std::string column, voxel; // statements before and inside the y loop
    std::vector<std::string_view> libraries;
};

FieldCode emitField(const ir::IrModule& module, const ir::IrField& field, std::string_view sourceName) {
    const std::vector<std::shared_ptr<const PointSet>> pointSets = pointSetsOf(module);
    FieldCode code;
    code.names.resize(field.nodes.size());
    std::set<std::string_view> seenLibraries;
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        if (node.kind == FieldNode::Kind::Constant) {
            code.names[i] = constantGlsl(node);
            continue;
        }
        std::string value, what;
        switch (node.kind) {
        case FieldNode::Kind::Constant: break;
        case FieldNode::Kind::Input:
            value = inputGlsl(node.input, module.world.localBase);
            what = std::array{"x", "y", "z", "wx", "wy", "wz"}[int(node.input)];
            break;
        case FieldNode::Kind::Component:
            value = code.names[node.operands[0]] + "." + "xyz"[node.component];
            what = "component";
            break;
        case FieldNode::Kind::PointSet: {
            const auto it = std::find(pointSets.begin(), pointSets.end(), node.pointSet);
            VOXC_ASSERT(it != pointSets.end());
            value = fmt::format("pointSetDistances({}, {})", it - pointSets.begin(), code.names[node.operands[0]]);
            what = "point set distances";
            if (seenLibraries.insert(kPointSetLibrary).second) code.libraries.push_back(kPointSetLibrary);
            break;
        }
        case FieldNode::Kind::Call: {
            const FunctionInfo& info = functions()[node.function];
            std::vector<std::string> args;
            std::vector<Type> types;
            for (uint32_t o : node.operands) {
                args.push_back(code.names[o]);
                types.push_back(field.nodes[o].type);
            }
            value = info.glsl(args, types);
            what = info.name;
            for (std::string_view library : info.glslLibraries)
                if (seenLibraries.insert(library).second) code.libraries.push_back(library);
            break;
        }
        }
        code.names[i] = fmt::format("n{}", i);
        const std::string line =
            fmt::format("{}{} {} = {}; // {} ({}:{}:{})\n", isFloatType(node.type) ? "precise " : "",
                        typeName(node.type), code.names[i], value, what, sourceName, node.loc.line, node.loc.column);
        (field.perColumn.at(i) ? code.column : code.voxel) += line;
    }
    return code;
}

// d = f, max(d, f), min(d, 1 - f), min(d, f), with std::max(a, b) = a < b ? b : a and
// std::min(a, b) = b < a ? b : a, so ties and signed zeros resolve as in the interpreter.
std::string combineDensityGlsl(FieldMode mode, const std::string& f) {
    const std::string store = "voxels.density[address] = ";
    const std::string load = "float density = voxels.density[address];\n";
    switch (mode) {
    case FieldMode::Set: return fmt::format("// set: d = f\n{}{};\n", store, f);
    case FieldMode::Union:
        return fmt::format("// union: d = max(d, f)\n{}{}density < {} ? {} : density;\n", load, store, f, f);
    case FieldMode::Subtract:
        return fmt::format("// subtract: d = min(d, 1 - f)\n{}precise float carved = 1.0 - {};\n"
                           "{}carved < density ? carved : density;\n",
                           load, f, store);
    case FieldMode::Intersect:
        return fmt::format("// intersect: d = min(d, f)\n{}{}{} < density ? {} : density;\n", load, store, f, f);
    case FieldMode::Paint: return "// paint without a material: nothing to write\n";
    }
    return {};
}

// voxc::combineField with a material: the same density as combineDensityGlsl, and material m
// where the field wins and the resulting density is solid.
std::string combineWithMaterialGlsl(FieldMode mode, uint8_t material, const std::string& f) {
    const std::string write = fmt::format("materials.material[address] = {}u;\n", material);
    const std::string solid = glslFloat(kSolidDensity);
    const std::string load = "float density = voxels.density[address];\n";
    std::string wins, result;
    switch (mode) {
    case FieldMode::Set:
        return fmt::format("// set: d = f; material {} where f is solid\nvoxels.density[address] = {};\n"
                           "if ({} >= {}) {}",
                           material, f, f, solid, write);
    case FieldMode::Paint:
        return fmt::format("// paint: d unchanged; material {} where f and d are solid\n"
                           "if ({} >= {} && voxels.density[address] >= {}) {}",
                           material, f, solid, solid, write);
    case FieldMode::Union:
        wins = fmt::format("// union: d = max(d, f); material {} where f wins and is solid\n{}"
                           "bool wins = density < {};\n", material, load, f);
        result = f;
        break;
    case FieldMode::Subtract:
        wins = fmt::format("// subtract: d = min(d, 1 - f); material {} where 1 - f wins and is solid\n{}"
                           "precise float carved = 1.0 - {};\nbool wins = carved < density;\n", material, load, f);
        result = "carved";
        break;
    case FieldMode::Intersect:
        wins = fmt::format("// intersect: d = min(d, f); material {} where f wins and is solid\n{}"
                           "bool wins = {} < density;\n", material, load, f);
        result = f;
        break;
    }
    return fmt::format("{}float result = wins ? {} : density;\nvoxels.density[address] = result;\n"
                       "if (wins && result >= {}) {}",
                       wins, result, solid, write);
}

std::string combineGlsl(FieldMode mode, std::optional<uint8_t> material, const std::string& f) {
    return material ? combineWithMaterialGlsl(mode, *material, f) : combineDensityGlsl(mode, f);
}

} // namespace

std::vector<std::shared_ptr<const PointSet>> pointSetsOf(const ir::IrModule& module) {
    std::vector<std::shared_ptr<const PointSet>> sets;
    for (const ir::IrField& field : module.fields)
        for (const FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::PointSet &&
                std::find(sets.begin(), sets.end(), node.pointSet) == sets.end())
                sets.push_back(node.pointSet);
    return sets;
}

DispatchShape fieldDispatchShape(const ir::IrModule& module) { return startDispatchShape(module); }

namespace {

// The combine with the constant c leaves every voxel as it is, density and material, for every
// density d in `before` (combineGlsl's comparisons, NaN-free).
bool combineKeepsVoxel(FieldMode mode, std::optional<uint8_t> material, float c, std::optional<DensityBounds> before) {
    if (mode == FieldMode::Paint) // d is kept; m is written where c >= 0.5 and d >= 0.5
        return !material || !(c >= kSolidDensity) || (before && !(before->hi >= kSolidDensity));
    if (!before) return false;
    // Where these keep d the field never wins, so the material is kept too.
    switch (mode) {
    case FieldMode::Set: return false;
    case FieldMode::Union: return !(before->lo < c);              // d < c ? c : d
    case FieldMode::Subtract: return !(1.0f - c < before->hi);    // carved < d ? carved : d
    case FieldMode::Intersect: return !(c < before->hi);          // c < d ? c : d
    case FieldMode::Paint: break;
    }
    return false;
}

// Float bounds around the double bounds [lo, hi] of a field (rounded outward), if finite.
std::optional<DensityBounds> floatBounds(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi || std::fabs(lo) > FLT_MAX || std::fabs(hi) > FLT_MAX)
        return std::nullopt;
    float l = float(lo), h = float(hi);
    if (double(l) > lo) l = std::nextafter(l, -INFINITY);
    if (double(h) < hi) h = std::nextafter(h, INFINITY);
    return DensityBounds{l, h};
}

// The densities after the combine, from those before and the field's bounds f. voxc::combineField
// is increasing in the density and in f, except subtract (decreasing in f), and its float operations
// round monotonically, so combining the ends bounds every result. A set ignores the densities.
std::optional<DensityBounds> densitiesAfter(FieldMode mode, std::optional<DensityBounds> d, double lo, double hi) {
    if (mode == FieldMode::Paint) return d;
    const std::optional<DensityBounds> f = floatBounds(lo, hi);
    if (!f || (!d && mode != FieldMode::Set)) return std::nullopt;
    const DensityBounds before = d.value_or(DensityBounds{});
    const bool decreasing = mode == FieldMode::Subtract;
    const auto combine = [mode](float density, float field) {
        return combineField(mode, std::nullopt, field, {density, kMaterialNone}).density;
    };
    return DensityBounds{combine(before.lo, decreasing ? f->hi : f->lo), combine(before.hi, decreasing ? f->lo : f->hi)};
}

// Merges boxes that touch along `axis` and agree on everything else (the other axes' extents,
// class, constant bits), so uniform regions become few large dispatches.
std::vector<FieldBox> mergeAlong(const std::vector<FieldBox>& boxes, int axis) {
    using Key = std::tuple<int, int, int, int, int, bool, uint32_t, bool>;
    const auto keyOf = [axis](const FieldBox& b, int end) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        return Key{b.min[u], b.max[u], b.min[v], b.max[v], end, b.constant, std::bit_cast<uint32_t>(b.value),
                   b.unchanged};
    };
    std::vector<FieldBox> merged;
    std::map<Key, size_t> openEnds; // a merged box by where it ends along the axis
    for (const FieldBox& box : boxes) {
        const auto it = openEnds.find(keyOf(box, box.min[axis]));
        if (it == openEnds.end()) {
            openEnds[keyOf(box, box.max[axis])] = merged.size();
            merged.push_back(box);
            continue;
        }
        const size_t index = it->second;
        openEnds.erase(it);
        merged[index].max[axis] = box.max[axis];
        openEnds[keyOf(merged[index], box.max[axis])] = index;
    }
    return merged;
}

} // namespace

FieldStageBoxes fieldBoxes(const ir::IrModule& module, const ir::IrField& field, FieldMode mode,
                           std::optional<uint8_t> material, std::optional<DensityBounds> before) {
    std::vector<FieldBox> boxes;
    glm::ivec3 lastChunk{0};
    double fieldLo = std::numeric_limits<double>::infinity(), fieldHi = -fieldLo;
    for (ir::FieldChunk chunk : ir::classifyFieldChunks(module.world, field)) {
        // Only a finite value may skip the field's evaluation, which counts non-finite values.
        chunk.constant = chunk.constant && std::isfinite(chunk.value);
        fieldLo = std::min(fieldLo, chunk.lo);
        fieldHi = std::max(fieldHi, chunk.hi);
        const bool extends = !boxes.empty() && chunk.chunk.x == lastChunk.x + 1 && chunk.chunk.y == lastChunk.y &&
                             chunk.chunk.z == lastChunk.z && boxes.back().constant == chunk.constant &&
                             std::bit_cast<uint32_t>(boxes.back().value) == std::bit_cast<uint32_t>(chunk.value);
        if (extends)
            boxes.back().max.x = chunk.localMax.x;
        else
            boxes.push_back(FieldBox{chunk.localMin, chunk.localMax, chunk.constant, chunk.value,
                                     chunk.constant && combineKeepsVoxel(mode, material, chunk.value, before)});
        lastChunk = chunk.chunk;
    }
    return {mergeAlong(mergeAlong(boxes, 1), 2), densitiesAfter(mode, before, fieldLo, fieldHi)};
}

std::string fieldKernelSource(const ir::IrModule& module, const ir::IrField& field, FieldMode mode,
                              std::optional<uint8_t> material, const std::vector<Stage>& stages, std::string_view kernelName,
                              std::string_view sourceName) {
    const FieldCode code = emitField(module, field, sourceName);
    std::string header = fmt::format("voxc generated kernel \"{}\": field {} ({}:{}:{}), mode {}.\nPipeline stage",
                                     kernelName, field.name, sourceName, field.loc.line, field.loc.column,
                                     ir::fieldModeName(mode));
    header += stages.size() == 1 ? "" : "s";
    for (const Stage& stage : stages)
        header += fmt::format(" `{}` ({}:{}:{})", ir::printStage(stage), sourceName, stage.loc.line,
                              stage.loc.column);
    header += ".\n";
    std::string libraries;
    for (std::string_view library : code.libraries) libraries += fmt::format("#include \"{}\"\n", library);
    if (libraries.empty()) libraries = "// No function library needed.\n";
    return instantiateTemplate(
        "field.glsl",
        {{"HEADER", prefixLines(header, "// ")},
         {"LIBRARIES", libraries},
         {"DISPATCH_SHAPE", dispatchShapeGlsl(fieldDispatchShape(module))},
         {"COLUMN_VALUES", code.column.empty() ? "// No value is the same along the column.\n" : code.column},
         {"VOXEL_VALUES", code.voxel.empty() ? "// Every value is the same along the column.\n" : code.voxel},
         {"CONSTANT_COMBINE", combineGlsl(mode, material, "constantValue")},
         {"COMBINE", fmt::format("float fieldValue = finiteDensity({}, local);\n", code.names.at(field.root)) +
                         combineGlsl(mode, material, "fieldValue")}});
}

} // namespace voxc::codegen

// GLSL for a field stage: the field's DAG as straight-line SSA code (one variable per node,
// constants written inline, those a driver could fold wrongly through opaqueConstant), the
// per-column nodes before the y loop, then the combine of FieldMode written exactly as
// voxc::combineField computes it with std::min / std::max.
#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Ops.h"
#include "voxc/codegen/PointSets.h"
#include "voxc/codegen/SampledMaps.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"
#include "voxc/program/PointSet.h"
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

// Records the device evaluates through exp2 and log2, not exactly (docs/architecture.md): with
// constant arguments the compilers evaluate them on the host (pow(2, 1.5)) or simplify them
// exactly (pow(x, 2) into x * x), as the interpreter's results are, so theirs stay literal.
constexpr std::string_view kInexactOnDevice[] = {"pow", "warped_fbm"};

bool constantsAlone(const ir::IrField& field, const FieldNode& node) {
    return std::all_of(node.operands.begin(), node.operands.end(),
                       [&](uint32_t o) { return field.nodes[o].kind == FieldNode::Kind::Constant; });
}

// The float constants the compilers must not see (opaque_constants.glsl): those zero in some
// component (their folds of x + 0, 0 - x, x * 0, x / 0 and 0 / x are not IEEE), and the arguments
// of a record whose GLSL calls into a library, whose own arithmetic may turn them into such a
// zero (mix(x, y, 1) computes x * (1 - 1)). A call on constants alone (one the IR does not fold,
// such as sqrt(4)) gets its operands as variables instead (constantCallOperands) and has its
// value made opaque (emitField), so the driver still evaluates it on the host but cannot fold what
// follows (sqrt(4) - 2 into a zero).
std::vector<bool> opaqueConstants(const ir::IrField& field) {
    std::vector<bool> opaque(field.nodes.size(), false);
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        if (node.kind == FieldNode::Kind::Constant && isFloatType(node.type))
            for (int c = 0; c < (node.type == Type::Vec3 ? 3 : node.type == Type::Vec2 ? 2 : 1); ++c)
                if (node.constant[c] == 0.0f) opaque[i] = true;
        if (node.kind != FieldNode::Kind::Call || constantsAlone(field, node)) continue;
        const FunctionInfo& info = functions()[node.function];
        if (info.glslLibraries.empty() || std::ranges::find(kInexactOnDevice, info.name) != std::end(kInexactOnDevice))
            continue;
        for (uint32_t o : node.operands)
            if (field.nodes[o].kind == FieldNode::Kind::Constant && isFloatType(field.nodes[o].type)) opaque[o] = true;
    }
    return opaque;
}

// The float constants that are operands of a call on constants alone. They are emitted as
// variables: glslang folds an expression of literals in double, from their decimal text
// (183.327194 / -3.612 is 1 ulp off the float quotient), while the driver folds the call on the
// variables' float values, as the interpreter computes it.
std::vector<bool> constantCallOperands(const ir::IrField& field) {
    std::vector<bool> operand(field.nodes.size(), false);
    for (const FieldNode& node : field.nodes)
        if (node.kind == FieldNode::Kind::Call && constantsAlone(field, node))
            for (uint32_t o : node.operands) operand[o] = isFloatType(field.nodes[o].type);
    return operand;
}

std::string opaqueGlsl(const std::string& constant) { return "opaqueConstant(" + constant + ")"; }

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

// The file's grid-local coordinate along `axis` (x, y or z: grid index + World::localBase) of the
// voxel whose world coordinate is the GLSL int `worldCoordinate`, as an int expression to pass as
// an argument: that coordinate less the declared grid's origin (World::origin - localBase), which
// every region of a world shares. So a region's place reaches the kernel only through the push
// constants (gridOrigin), and equal-sized tiles of a world compile to the same kernels
// (docs/scale.md, "Where a tile's time goes").
std::string fileLocalGlsl(const World& world, int axis, std::string_view worldCoordinate) {
    const int32_t declaredOrigin = world.origin[axis] - world.localBase[axis];
    if (declaredOrigin == 0) return std::string(worldCoordinate);
    return fmt::format("{} - ({})", worldCoordinate, declaredOrigin);
}

// wx, wy, wz are the voxel's world coordinate; x, y, z its file's grid-local one (fileLocalGlsl),
// an integer difference converted once, as the interpreter sums grid index and World::localBase.
std::string inputGlsl(FieldInput input, const World& world) {
    const int axis = int(input) % 3;
    const std::string coordinate = fmt::format("{}.{}", axis != 1 ? "columnWorld" : "world", "xyz"[axis]);
    return fmt::format("float({})", input >= FieldInput::WorldX ? coordinate : fileLocalGlsl(world, axis, coordinate));
}

// Declares binding kBindingPointSets and pointSetDistances.
constexpr std::string_view kPointSetLibrary = "lsystem_carve.glsl";
// mapSample over binding kBindingSolveTables (solve_tables.glsl), NaN tested as math_functions.glsl does.
constexpr std::string_view kMapLibraries[] = {"math_functions.glsl", "solve_tables.glsl", "map_sample.glsl"};

// Each node's GLSL: a variable name, or the literal of a constant.
struct FieldCode {
    std::vector<std::string> names;
    std::string column, voxel; // statements before and inside the y loop
    std::vector<std::string_view> libraries;
    // Noise calls and point-set lookups the column shares work for (noise_column.glsl,
    // point_set_column.glsl): the kernel's declarations, and the fills at the start of each block
    // of the column.
    std::string columnNoise, columnPointSets, block;
    std::string columnPointSetArgY; // pointSetColumnArgY's cases
};

// Whether componentGlsl's expression for node `i`'s component `axis` is built from constants alone.
template <class Leaf>
bool constantComponent(const ir::IrField& field, uint32_t i, int axis, const Leaf& leaf) {
    const FieldNode& node = field.nodes[i];
    if (node.kind == FieldNode::Kind::Constant) return true;
    if (leaf(i, axis)) return false;
    if (node.kind == FieldNode::Kind::Component) return constantComponent(field, node.operands[0], int(node.component), leaf);
    if (node.kind != FieldNode::Kind::Call) return false;
    const std::string_view name = functions()[node.function].name;
    if (name == "vec3") return constantComponent(field, node.operands[axis], axis, leaf);
    if (name == "neg") return constantComponent(field, node.operands[0], axis, leaf);
    return (name == "add" || name == "sub" || name == "mul") && constantComponent(field, node.operands[0], axis, leaf) &&
           constantComponent(field, node.operands[1], axis, leaf);
}

// A float or vec3 node's component `axis` as one GLSL expression, when the node is built from
// vec3 constructors, constants, component reads, sums, differences, products and negations over
// leaves that `leaf` names (scalar nodes it accepts). The operations are the ones the vector code
// performs on that component, in the same order, so an expression assigned to a `precise`
// variable has the same bits as the component of the node's value.
template <class Leaf>
std::optional<std::string> componentGlsl(const ir::IrField& field, const std::vector<bool>& opaque, uint32_t i, int axis,
                                         const Leaf& leaf) {
    const FieldNode& node = field.nodes[i];
    if (node.type != Type::Float && node.type != Type::Vec3) return std::nullopt;
    if (node.kind == FieldNode::Kind::Constant) {
        const std::string c = glslFloat(node.type == Type::Float ? node.constant.x : node.constant[axis]);
        return opaque[i] ? opaqueGlsl(c) : c;
    }
    if (std::optional<std::string> named = leaf(i, axis)) return named;
    if (node.kind == FieldNode::Kind::Component)
        return field.nodes[node.operands[0]].type == Type::Vec3
                   ? componentGlsl(field, opaque, node.operands[0], int(node.component), leaf)
                   : std::nullopt;
    if (node.kind != FieldNode::Kind::Call) return std::nullopt;
    const std::string_view name = functions()[node.function].name;
    if (name == "vec3") return componentGlsl(field, opaque, node.operands[axis], axis, leaf);
    if (name == "neg") {
        const std::optional<std::string> a = componentGlsl(field, opaque, node.operands[0], axis, leaf);
        return a ? std::optional("(-" + *a + ")") : std::nullopt;
    }
    const char* op = name == "add" ? "+" : name == "sub" ? "-" : name == "mul" ? "*" : nullptr;
    if (!op) return std::nullopt;
    const std::optional<std::string> a = componentGlsl(field, opaque, node.operands[0], axis, leaf);
    const std::optional<std::string> b = componentGlsl(field, opaque, node.operands[1], axis, leaf);
    if (!a || !b) return std::nullopt;
    // glslang folds an operation on literals itself, in double from their decimal text (5.0 *
    // 0.300000012 is 1.5000001, the float product 1.5); through driverFolded the driver folds it,
    // in float.
    const bool literals = constantComponent(field, node.operands[0], axis, leaf) &&
                          constantComponent(field, node.operands[1], axis, leaf);
    return fmt::format("({} {} {})", literals ? "driverFolded(" + *a + ")" : *a, op, *b);
}

// The y of a column walk's point as a function of worldY (the voxel's world y), when the point's
// y depends on y alone and its x and z are the same along the column (nullopt otherwise), with
// the column's x and z in `x` and `z`.
std::optional<std::string> columnPointY(const ir::IrModule& module, const ir::IrField& field,
                                        const std::vector<bool>& opaque, uint32_t point,
                                        const std::vector<std::string>& names, std::string& x, std::string& z) {
    const auto columnLeaf = [&](uint32_t n, int axis) -> std::optional<std::string> {
        if (!field.perColumn.at(n)) return std::nullopt;
        if (field.nodes[n].type == Type::Vec3) return fmt::format("{}.{}", names[n], "xyz"[axis]);
        return names[n];
    };
    const auto alongYLeaf = [&](uint32_t n, int) -> std::optional<std::string> {
        const FieldNode& leaf = field.nodes[n];
        if (leaf.kind != FieldNode::Kind::Input || int(leaf.input) % 3 != 1) return std::nullopt;
        if (leaf.input == FieldInput::WorldY) return "float(worldY)";
        return fmt::format("float({})", fileLocalGlsl(module.world, 1, "worldY"));
    };
    const std::optional<std::string> columnX = componentGlsl(field, opaque, point, 0, columnLeaf);
    const std::optional<std::string> y = componentGlsl(field, opaque, point, 1, alongYLeaf);
    const std::optional<std::string> columnZ = componentGlsl(field, opaque, point, 2, columnLeaf);
    if (!columnX || !y || !columnZ) return std::nullopt;
    x = *columnX;
    z = *columnZ;
    return y;
}

// Voxels of a column one fill of the column noise covers (field.glsl's COLUMN_BLOCK), or
// kPointSetColumnBlock in a kernel with point-set lookups along the column.
constexpr int kColumnBlock = 256;

// Each column noise call holds a block of COLUMN_BLOCK floats per invocation (1 KiB); past this
// many in one kernel the calls are evaluated per voxel, so private memory stays small on a GPU.
constexpr int kMaxColumnNoiseSites = 4;

// Emits call `i` through noise_column.glsl when it is fbm, turbulence or perlin3 of a point whose
// x and z are the same along the column and whose y depends on y alone, its other arguments the
// same along the column; false otherwise (the call is then emitted per voxel).
bool emitColumnNoise(const ir::IrModule& module, const ir::IrField& field, const std::vector<bool>& opaque, uint32_t i,
                     int site, FieldCode& code) {
    const FieldNode& node = field.nodes[i];
    const std::string_view name = functions()[node.function].name;
    const bool fractal = name == "fbm" || name == "turbulence";
    if ((!fractal && name != "perlin3") || site >= kMaxColumnNoiseSites) return false;
    for (size_t k = 1; k < node.operands.size(); ++k)
        if (!field.perColumn.at(node.operands[k])) return false;
    std::string x, z;
    const std::optional<std::string> y = columnPointY(module, field, opaque, node.operands[0], code.names, x, z);
    if (!y) return false;
    const std::vector<uint32_t>& a = node.operands;
    const std::string arguments =
        fractal ? fmt::format("{}, {}, {}, uint({}), {}", code.names[a[1]], code.names[a[2]], code.names[a[3]],
                              code.names[a[4]], name == "fbm" ? 0 : 1)
                : fmt::format("1, 1.0, 1.0, uint({}), 0", code.names[a[1]]); // one fbm octave is perlin3, bit for bit
    code.column += fmt::format("precise float noiseColumnX{0} = {1};\nprecise float noiseColumnZ{0} = {2};\n", site, x, z);
    code.block += fmt::format("noiseColumnFill({0}, blockY, blockEnd, noiseColumnX{0}, noiseColumnZ{0}, {1});\n", site, arguments);
    code.columnNoise += fmt::format("    case {}: {{ precise float r = {}; return r; }}\n", site, *y);
    return true;
}

// Point-set lookups along the column hold 8 vec2 per invocation (pointSetColumnFill fills a
// block of 8 voxels); past this many in one kernel they are made per voxel.
constexpr int kMaxColumnPointSetSites = 4;
constexpr int kPointSetColumnBlock = 8;
// Voxels one invocation walks along y where every point-set lookup of the field is shared along
// the column (instead of kPointSetAnchorsAlongY): a block of 8 loops at most 2 cells x 2 lists x
// (8192 / 8 + 1) times, so 4 blocks stay far under lavapipe's 65,535 iterations, and a longer walk
// pays an invocation's own costs (its column values, the lists' headers) for more voxels.
constexpr uint32_t kPointSetColumnAnchorsAlongY = 32;

// Emits point-set node `i` (of set `set`) through point_set_column.glsl when its point's x and z
// are the same along the column and its y depends on y alone: the block's fill looks the voxels
// up together; false otherwise (the lookup is then emitted per voxel).
bool emitColumnPointSet(const ir::IrModule& module, const ir::IrField& field, const std::vector<bool>& opaque,
                        uint32_t i, ptrdiff_t set, int site, FieldCode& code) {
    if (site >= kMaxColumnPointSetSites) return false;
    std::string x, z;
    const std::optional<std::string> y = columnPointY(module, field, opaque, field.nodes[i].operands[0], code.names, x, z);
    if (!y) return false;
    code.column += fmt::format("precise float pointSetColumnX{0} = {1};\nprecise float pointSetColumnZ{0} = {2};\n", site, x, z);
    code.block += fmt::format("pointSetColumnFill({0}, {1}, pointSetColumnX{0}, pointSetColumnZ{0}, blockY, blockEnd, "
                              "pointSetColumnValues{0});\n", site, set);
    code.columnPointSets += fmt::format("vec2 pointSetColumnValues{}[{}];\n", site, kPointSetColumnBlock);
    code.columnPointSetArgY += fmt::format("    case {}: {{ precise float r = {}; return r; }}\n", site, *y);
    return true;
}

// Whether every lookup of a point set in `field` that depends on y is emitted along the column
// (emitField's emitColumnPointSet), so none is made per voxel.
bool pointSetLookupsAlongColumn(const ir::IrModule& module, const ir::IrField& field) {
    const std::vector<bool> opaque = opaqueConstants(field);
    const std::vector<std::string> names(field.nodes.size());
    int sites = 0;
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        if (node.kind != FieldNode::Kind::PointSet || field.perColumn.at(i)) continue;
        std::string x, z;
        if (++sites > kMaxColumnPointSetSites || !columnPointY(module, field, opaque, node.operands[0], names, x, z))
            return false;
    }
    return true;
}

// ---- Noise skip ----
// A voxel whose field value its cheap nodes already settle, whatever values the costliest calls
// take inside their ranges, skips those calls. The records skipped: the worley family, each a
// search of 27 cells and most of a carve's time. The kernel bounds every node computed from them
// by their ranges (the registry's range rules, voxc/builtins/Intervals.h, which hold the device's
// values too) and the exact values of
// the rest; where the root's bounds are one float it takes that float and leaves the calls and
// their dependents to a loop it does not enter (llvmpipe runs both sides of an `if`, but leaves a
// loop that no lane of a group is in).
// Same bits: add, sub, mul, neg, min, max and clamp are monotone in each operand (for mul, the
// extremes lie at the operands' corners) and float rounding is monotone, so the same float
// operations at the ends bound the kernel's value; bounds equal as numbers are the value, signed
// zero aside, which only a combine that ignores a zero's sign may take (FieldMode Subtract, Paint).
constexpr std::string_view kSkippableCalls[] = {"worley_f1", "worley_f2", "worley_f2f1"};
// The operations a value computed from a skipped call may pass through (scalar floats only).
constexpr std::string_view kBoundedOperations[] = {"add", "sub", "mul", "neg", "min", "max", "clamp"};
// Bounds past this are treated as unbounded, so no bound computation can overflow into a NaN.
constexpr double kSkipBoundLimit = 1e30;

struct NoiseSkip {
    std::vector<bool> skipped;   // calls a settled voxel does not evaluate
    std::vector<bool> dependent; // skipped, or computed from a skipped call
    std::vector<float> lo, hi;   // the skipped calls' float ranges
    bool rootMayBeZero = true;   // whether settling on a zero needs its sign (the combine's)
};

bool boundedFinite(const Interval& v) {
    return v.type == Type::Float && std::fabs(v.lo.x) <= kSkipBoundLimit && std::fabs(v.hi.x) <= kSkipBoundLimit;
}

// The noise skip of a column-walking field kernel, or nullopt where no call can be skipped.
std::optional<NoiseSkip> planNoiseSkip(const ir::IrField& field, FieldMode mode) {
    // Every voxel's coordinates are ints converted to float: any value of an int bounds them.
    const double coordinate = double(float(INT32_MAX));
    std::array<Interval, 6> inputs;
    inputs.fill(Interval{Type::Float, {-coordinate, 0, 0}, {coordinate, 0, 0}, false});
    const std::vector<Interval> ranges = ir::fieldNodeIntervals(field, inputs);
    const size_t count = field.nodes.size();
    NoiseSkip skip{std::vector<bool>(count, false), std::vector<bool>(count, false), std::vector<float>(count, 0.0f),
                   std::vector<float>(count, 0.0f), mode != FieldMode::Subtract && mode != FieldMode::Paint};
    bool any = false;
    for (size_t i = 0; i < count; ++i) {
        const FieldNode& node = field.nodes[i];
        if (field.perColumn.at(i)) continue;
        if (node.kind == FieldNode::Kind::Call && node.type == Type::Float &&
            std::ranges::find(kSkippableCalls, functions()[node.function].name) != std::end(kSkippableCalls) &&
            boundedFinite(ranges[i])) {
            skip.skipped[i] = skip.dependent[i] = any = true;
            // Float ends outside the double bounds (every float value lies between them).
            skip.lo[i] = std::nextafter(float(ranges[i].lo.x), -INFINITY);
            skip.hi[i] = std::nextafter(float(ranges[i].hi.x), INFINITY);
            continue;
        }
        for (uint32_t o : node.operands) skip.dependent[i] = skip.dependent[i] || skip.dependent[o];
        if (!skip.dependent[i]) continue;
        const bool bounded = node.kind == FieldNode::Kind::Call && node.type == Type::Float && boundedFinite(ranges[i]) &&
                             std::ranges::find(kBoundedOperations, functions()[node.function].name) !=
                                 std::end(kBoundedOperations) &&
                             std::all_of(node.operands.begin(), node.operands.end(),
                                         [&](uint32_t o) { return boundedFinite(ranges[o]); });
        if (!bounded) return std::nullopt;
    }
    if (!any || !skip.dependent[field.root] || skip.skipped[field.root]) return std::nullopt;
    return skip;
}

// The bounds of the nodes computed from skipped calls (nLo, nHi per node n), the test whether the
// root is settled, and the loop that evaluates the skipped calls and their dependents elsewhere.
// `statements` holds those nodes' assignments in node order.
std::string noiseSkipGlsl(const ir::IrField& field, const NoiseSkip& skip, const std::vector<std::string>& names,
                          const std::string& statements) {
    std::string declarations, bounds;
    const auto end = [&](uint32_t o, bool high) -> std::string {
        if (skip.skipped[o]) return opaqueGlsl(glslFloat(high ? skip.hi[o] : skip.lo[o]));
        return skip.dependent[o] ? names[o] + (high ? "Hi" : "Lo") : names[o];
    };
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        if (!skip.dependent[i]) continue;
        declarations += fmt::format("precise float {};\n", names[i]);
        if (skip.skipped[i]) continue;
        const FieldNode& node = field.nodes[i];
        const FunctionInfo& info = functions()[node.function];
        const std::vector<Type> types(node.operands.size(), Type::Float);
        const auto call = [&](std::vector<bool> high) {
            std::vector<std::string> args;
            for (size_t k = 0; k < node.operands.size(); ++k) args.push_back(end(node.operands[k], high[k]));
            return info.glsl(args, types);
        };
        std::string lo, hi;
        if (info.name == "sub") {
            lo = call({false, true});
            hi = call({true, false});
        } else if (info.name == "neg") {
            lo = call({true});
            hi = call({false});
        } else if (info.name == "mul") {
            // The products at the corners; an exact operand has one end.
            std::vector<std::string> corners;
            for (bool a : {false, true})
                for (bool b : {false, true})
                    if ((a == false || skip.dependent[node.operands[0]]) && (b == false || skip.dependent[node.operands[1]]))
                        corners.push_back(call({a, b}));
            for (size_t k = 0; k < corners.size(); ++k)
                bounds += fmt::format("precise float {}Corner{} = {};\n", names[i], k, corners[k]);
            lo = names[i] + "Corner0";
            hi = lo;
            for (size_t k = 1; k < corners.size(); ++k) {
                lo = fmt::format("min({}, {}Corner{})", lo, names[i], k);
                hi = fmt::format("max({}, {}Corner{})", hi, names[i], k);
            }
        } else { // add, min, max, clamp: increasing in every operand
            lo = call(std::vector<bool>(node.operands.size(), false));
            hi = call(std::vector<bool>(node.operands.size(), true));
        }
        bounds += fmt::format("precise float {0}Lo = {1};\nprecise float {0}Hi = {2};\n", names[i], lo, hi);
    }
    const std::string& root = names[field.root];
    return fmt::format("// Noise skip: bounds of the values computed from the skipped calls' ranges.\n{}{}"
                       "bool noiseSkipSettled = {}Lo == {}Hi{};\n{} = {}Lo;\n"
                       "for (int noiseSkip = noiseSkipSettled ? 1 : 0; noiseSkip < 1; ++noiseSkip) {{\n{}}}\n",
                       declarations, bounds, root, root, skip.rootMayBeZero ? fmt::format(" && {}Lo != 0.0", root) : "",
                       root, root, prefixLines(statements, "    "));
}

// x, y, z in a stamp's frame (`stampPosition`, voxc::stampLocal); wx, wy, wz the voxel's world place.
std::string stampInputGlsl(FieldInput input) {
    const int axis = int(input) % 3;
    return input >= FieldInput::WorldX ? fmt::format("float(world.{})", "xyz"[axis])
                                       : fmt::format("stampPosition.{}", "xyz"[axis]);
}

// `stampFrame`: the inputs of a stamp, every node in `voxel` (no column walk).
FieldCode emitField(const ir::IrModule& module, const ir::IrField& field, std::string_view sourceName,
                    bool stampFrame = false, const NoiseSkip* skip = nullptr) {
    const std::vector<std::shared_ptr<const PointSet>> pointSets = pointSetsOf(module);
    const std::vector<std::shared_ptr<const SampledMap>> maps = mapsOf(module);
    FieldCode code;
    code.names.resize(field.nodes.size());
    const std::vector<bool> opaque = opaqueConstants(field);
    const std::vector<bool> asVariable = constantCallOperands(field);
    std::set<std::string_view> seenLibraries;
    int columnNoiseSites = 0, columnPointSetSites = 0;
    std::string skippable; // the assignments of the nodes a settled voxel skips
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        if (node.kind == FieldNode::Kind::Constant) {
            code.names[i] = opaque[i] ? opaqueGlsl(constantGlsl(node)) : constantGlsl(node);
            if (!asVariable[i]) continue;
        }
        std::string value, what;
        switch (node.kind) {
        case FieldNode::Kind::Constant:
            value = code.names[i];
            what = "constant, for the driver to fold in float";
            break;
        case FieldNode::Kind::Input:
            value = stampFrame ? stampInputGlsl(node.input) : inputGlsl(node.input, module.world);
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
            if (!stampFrame && !field.perColumn.at(i) &&
                emitColumnPointSet(module, field, opaque, uint32_t(i), it - pointSets.begin(), columnPointSetSites, code)) {
                value = fmt::format("pointSetColumnValues{}[y - blockY]", columnPointSetSites++);
                what += " along the column";
            }
            break;
        }
        case FieldNode::Kind::Map: {
            const auto it = std::find(maps.begin(), maps.end(), node.map);
            VOXC_ASSERT(it != maps.end());
            const SampledMap& map = *node.map;
            if (map.dimensions == 2)
                value = fmt::format("mapSample({}, {}, {}, {}, {}, {}, {})", it - maps.begin(), glslFloat(map.origin.x),
                                    glslFloat(map.origin.z), glslFloat(map.cellsPerVoxel.x),
                                    glslFloat(map.cellsPerVoxel.z), code.names[node.operands[0]],
                                    code.names[node.operands[1]]);
            else
                value = fmt::format("volumeSample({}, vec3({}, {}, {}), vec3({}, {}, {}), {}, {}, {})", it - maps.begin(),
                                    glslFloat(map.origin.x), glslFloat(map.origin.y), glslFloat(map.origin.z),
                                    glslFloat(map.cellsPerVoxel.x), glslFloat(map.cellsPerVoxel.y),
                                    glslFloat(map.cellsPerVoxel.z), code.names[node.operands[0]],
                                    code.names[node.operands[1]], code.names[node.operands[2]]);
            what = "map " + map.name;
            for (std::string_view library : kMapLibraries)
                if (seenLibraries.insert(library).second) code.libraries.push_back(library);
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
            if (isFloatType(node.type) && constantsAlone(field, node)) value = opaqueGlsl(value);
            what = info.name;
            for (std::string_view library : info.glslLibraries)
                if (seenLibraries.insert(library).second) code.libraries.push_back(library);
            if (!stampFrame && !field.perColumn.at(i) &&
                emitColumnNoise(module, field, opaque, uint32_t(i), columnNoiseSites, code)) {
                value = fmt::format("noiseColumnValues[{}][y - blockY]", columnNoiseSites++);
                what += " along the column";
            }
            break;
        }
        }
        code.names[i] = fmt::format("n{}", i);
        if (skip && skip->dependent[i]) { // declared before the skip's loop, assigned in it
            skippable += fmt::format("{} = {}; // {} ({}:{}:{})\n", code.names[i], value, what, sourceName,
                                     node.loc.line, node.loc.column);
            continue;
        }
        const std::string line =
            fmt::format("{}{} {} = {}; // {} ({}:{}:{})\n", isFloatType(node.type) ? "precise " : "",
                        typeName(node.type), code.names[i], value, what, sourceName, node.loc.line, node.loc.column);
        (field.perColumn.at(i) && !stampFrame ? code.column : code.voxel) += line;
    }
    if (skip) code.voxel += noiseSkipGlsl(field, *skip, code.names, skippable);
    if (columnNoiseSites > 0) {
        code.libraries.push_back("noise_column.glsl");
        code.columnNoise = fmt::format("float noiseColumnValues[{}][COLUMN_BLOCK];\n"
                                       "// Each column noise call's argument: its y at the column's voxel y.\n"
                                       "float noiseColumnArgY(int site, int y) {{\n"
                                       "    int localY = push.anchorStart.y + y * push.anchorStep.y;\n"
                                       "    int worldY = push.gridOrigin.y + localY;\n"
                                       "    switch (site) {{\n{}    }}\n    return 0.0;\n}}\n",
                                       columnNoiseSites, code.columnNoise);
    }
    if (columnPointSetSites > 0) {
        code.libraries.push_back("point_set_column.glsl");
        code.columnPointSets += fmt::format("// Each column point-set lookup's point: its y at the column's voxel y.\n"
                                            "float pointSetColumnArgY(int site, int y) {{\n"
                                            "    int localY = push.anchorStart.y + y * push.anchorStep.y;\n"
                                            "    int worldY = push.gridOrigin.y + localY;\n"
                                            "    switch (site) {{\n{}    }}\n    return 0.0;\n}}\n",
                                            code.columnPointSetArgY);
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

StampFieldCode stampFieldGlsl(const ir::IrModule& module, const ir::IrField& field, std::string_view sourceName) {
    FieldCode code = emitField(module, field, sourceName, true);
    return {std::move(code.voxel), code.names.at(field.root), std::move(code.libraries)};
}

std::string combineFieldGlsl(FieldMode mode, std::optional<uint8_t> material, const std::string& f) {
    return combineGlsl(mode, material, f);
}

std::vector<std::shared_ptr<const PointSet>> pointSetsOf(const ir::IrModule& module) {
    std::vector<std::shared_ptr<const PointSet>> sets;
    for (const ir::IrField& field : module.fields)
        for (const FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::PointSet &&
                std::find(sets.begin(), sets.end(), node.pointSet) == sets.end())
                sets.push_back(node.pointSet);
    return sets;
}

uint32_t fieldPointSetListBlock(const ir::IrField& field) {
    // One point set's iterations per voxel at its limit in blocks of kPointSetListBlock.
    constexpr uint64_t kLimitIterations = 2 * ((kMaxPointSetPerCell + kPointSetListBlock - 1) / kPointSetListBlock + 1);
    uint64_t iterations = 0;
    for (const FieldNode& node : field.nodes)
        if (node.kind == FieldNode::Kind::PointSet && node.pointSet)
            iterations += pointSetLookupIterations(node.pointSet->bins, 1);
    return iterations <= kLimitIterations ? 1 : kPointSetListBlock;
}

DispatchShape fieldDispatchShape(const ir::IrModule& module, const ir::IrField& field) {
    DispatchShape shape = startDispatchShape(module);
    const bool readsPointSet = std::any_of(field.nodes.begin(), field.nodes.end(),
                                           [](const FieldNode& node) { return node.kind == FieldNode::Kind::PointSet; });
    if (readsPointSet)
        shape.anchorsPerInvocation[1] =
            std::min(shape.anchorsPerInvocation[1],
                     pointSetLookupsAlongColumn(module, field) ? kPointSetColumnAnchorsAlongY : kPointSetAnchorsAlongY);
    return shape;
}

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
    const std::optional<NoiseSkip> skip = planNoiseSkip(field, mode);
    const FieldCode code = emitField(module, field, sourceName, false, skip ? &*skip : nullptr);
    std::string header = fmt::format("voxc generated kernel \"{}\": field {} ({}:{}:{}), mode {}.\nPipeline stage",
                                     kernelName, field.name, sourceName, field.loc.line, field.loc.column,
                                     ir::fieldModeName(mode));
    header += stages.size() == 1 ? "" : "s";
    for (const Stage& stage : stages)
        header += fmt::format(" `{}` ({}:{}:{})", ir::printStage(stage), sourceName, stage.loc.line,
                              stage.loc.column);
    header += ".\n";
    std::string libraries;
    if (std::ranges::find(code.libraries, kPointSetLibrary) != code.libraries.end())
        libraries += fmt::format("#define POINT_SET_BLOCK {}\n", fieldPointSetListBlock(field));
    for (std::string_view library : code.libraries) libraries += fmt::format("#include \"{}\"\n", library);
    if (libraries.empty()) libraries = "// No function library needed.\n";
    return instantiateTemplate(
        "field.glsl",
        {{"HEADER", prefixLines(header, "// ")},
         {"LIBRARIES", libraries},
         {"DISPATCH_SHAPE", dispatchShapeGlsl(fieldDispatchShape(module, field))},
         {"COLUMN_BLOCK", fmt::format("const int COLUMN_BLOCK = {};\n",
                                      code.columnPointSets.empty() ? kColumnBlock : kPointSetColumnBlock)},
         {"COLUMN_NOISE", code.columnNoise.empty() ? "// No noise call shares work along the column.\n" : code.columnNoise},
         {"COLUMN_POINT_SETS",
          code.columnPointSets.empty() ? "// No point-set lookup shares work along the column.\n" : code.columnPointSets},
         {"COLUMN_VALUES", code.column.empty() ? "// No value is the same along the column.\n" : code.column},
         {"BLOCK_VALUES", code.block.empty() ? "// Nothing to fill per block.\n" : code.block},
         {"VOXEL_VALUES", code.voxel.empty() ? "// Every value is the same along the column.\n" : code.voxel},
         {"CONSTANT_COMBINE", combineGlsl(mode, material, "constantValue")},
         {"COMBINE", fmt::format("float fieldValue = fieldDensity({}, local);\n", code.names.at(field.root)) +
                         combineGlsl(mode, material, "fieldValue")}});
}

} // namespace voxc::codegen

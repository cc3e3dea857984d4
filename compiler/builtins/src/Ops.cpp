#include "voxc/builtins/Ops.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace voxc {

namespace {

std::string compare(const std::string& density, const char* op, const std::string& value) {
    return fmt::format("({} {} {})", density, op, value);
}

// Densities are compared exactly (digest §1, decision 5); ABS and PRES compare with zero.
const SymbolOpInfo kSymbolOps[] = {
    {SymbolOp::IGN, "IGN", false, [](float, float) { return true; }, [](float) { return ValueSet::all(); },
     [](const std::string&, const std::string&) { return std::string("true"); },
     "a symbol cell that always passes, whatever the density"},
    {SymbolOp::PRES, "PRES", false, [](float d, float) { return d > 0.0f; },
     [](float) { return ValueSet::above(0.0f, false); },
     [](const std::string& d, const std::string&) { return compare(d, ">", "0.0"); },
     "passes when the density d > 0 (rock or anything not air)"},
    {SymbolOp::ABS, "ABS", false, [](float d, float) { return d == 0.0f; },
     [](float) { return ValueSet::point(0.0f); },
     [](const std::string& d, const std::string&) { return compare(d, "==", "0.0"); },
     "passes when the density d == 0 (air)"},
    {SymbolOp::EQ, "EQ", true, [](float d, float v) { return d == v; }, [](float v) { return ValueSet::point(v); },
     [](const std::string& d, const std::string& v) { return compare(d, "==", v); },
     "EQ v: passes when the density d == v (exactly)"},
    {SymbolOp::NEQ, "NEQ", true, [](float d, float v) { return d != v; }, [](float v) { return ValueSet::allBut(v); },
     [](const std::string& d, const std::string& v) { return compare(d, "!=", v); },
     "NEQ v: passes when the density d != v"},
    {SymbolOp::LT, "LT", true, [](float d, float v) { return d < v; },
     [](float v) { return ValueSet::below(v, false); },
     [](const std::string& d, const std::string& v) { return compare(d, "<", v); },
     "LT v: passes when the density d < v"},
    {SymbolOp::LEQ, "LEQ", true, [](float d, float v) { return d <= v; },
     [](float v) { return ValueSet::below(v, true); },
     [](const std::string& d, const std::string& v) { return compare(d, "<=", v); },
     "LEQ v: passes when the density d <= v"},
    {SymbolOp::GT, "GT", true, [](float d, float v) { return d > v; },
     [](float v) { return ValueSet::above(v, false); },
     [](const std::string& d, const std::string& v) { return compare(d, ">", v); },
     "GT v: passes when the density d > v"},
    {SymbolOp::GEQ, "GEQ", true, [](float d, float v) { return d >= v; },
     [](float v) { return ValueSet::above(v, true); },
     [](const std::string& d, const std::string& v) { return compare(d, ">=", v); },
     "GEQ v: passes when the density d >= v"},
};

const TransformOpInfo kTransformOps[] = {
    {TransformOp::NOP, "NOP", false, false, [](float d, float) { return d; },
     [](const std::string& d, const std::string&) { return d; },
     "writes nothing: the voxel is left untouched (and not clamped)"},
    {TransformOp::SET, "SET", true, true, [](float, float v) { return v; },
     [](const std::string&, const std::string& v) { return v; },
     "SET v: writes v"},
    {TransformOp::ADD, "ADD", true, true, [](float d, float v) { return d + v; },
     [](const std::string& d, const std::string& v) { return fmt::format("({} + {})", d, v); },
     "ADD v: writes d + v"},
};

const MaterialOpInfo kMaterialOps[] = {
    {MaterialOp::MAT, "MAT", [](uint8_t m, uint8_t id) { return m == id; },
     [](const std::string& m, const std::string& id) { return compare(m, "==", id); },
     "MAT m: in a symbol, passes when the voxel's material is m; in a transform, writes material m"},
    {MaterialOp::NMAT, "NMAT", [](uint8_t m, uint8_t id) { return m != id; },
     [](const std::string& m, const std::string& id) { return compare(m, "!=", id); },
     "NMAT m: passes when the voxel's material is not m"},
};

} // namespace

std::span<const SymbolOpInfo> symbolOps() { return kSymbolOps; }
std::span<const MaterialOpInfo> materialOps() { return kMaterialOps; }

const MaterialOpInfo& materialOpInfo(MaterialOp op) {
    for (const MaterialOpInfo& info : kMaterialOps)
        if (info.op == op) return info;
    throw InternalError("unknown material operator");
}

std::optional<MaterialOp> findMaterialOp(std::string_view name) {
    for (const MaterialOpInfo& info : kMaterialOps)
        if (info.name == name) return info.op;
    return std::nullopt;
}
std::span<const TransformOpInfo> transformOps() { return kTransformOps; }

const SymbolOpInfo& symbolOpInfo(SymbolOp op) {
    for (const SymbolOpInfo& info : kSymbolOps)
        if (info.op == op) return info;
    throw InternalError("unknown symbol operator");
}

const TransformOpInfo& transformOpInfo(TransformOp op) {
    for (const TransformOpInfo& info : kTransformOps)
        if (info.op == op) return info;
    throw InternalError("unknown transform operator");
}

std::optional<SymbolOp> findSymbolOp(std::string_view name) {
    for (const SymbolOpInfo& info : kSymbolOps)
        if (info.name == name) return info.op;
    return std::nullopt;
}

std::optional<TransformOp> findTransformOp(std::string_view name) {
    for (const TransformOpInfo& info : kTransformOps)
        if (info.name == name) return info.op;
    return std::nullopt;
}

std::string glslFloat(float v) {
    VOXC_ASSERT(std::isfinite(v));
    // Nine significant digits round-trip every float32 exactly.
    std::string s = fmt::format("{:.9g}", v);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

bool cellPasses(const SymbolCell& cell, float density, uint8_t material) {
    return std::all_of(cell.predicates.begin(), cell.predicates.end(),
                       [&](const Predicate& p) { return symbolOpInfo(p.op).eval(density, p.value); }) &&
           std::all_of(cell.materialPredicates.begin(), cell.materialPredicates.end(),
                       [&](const MaterialPredicate& p) { return materialOpInfo(p.op).eval(material, p.material); });
}

float applyTransform(const TransformCell& cell, float density, const Grammar& grammar) {
    const TransformOpInfo& info = transformOpInfo(cell.op);
    if (!info.writes) return density;
    float v = info.eval(density, cell.value);
    if (grammar.clampMin) v = std::max(v, *grammar.clampMin);
    if (grammar.clampMax) v = std::min(v, *grammar.clampMax);
    return v;
}

} // namespace voxc

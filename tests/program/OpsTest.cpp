// The operator registry: every operator's interpreter semantics, arity and set semantics.
#include "ProgramText.h"
#include "voxc/builtins/Ops.h"

#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <set>
#include <limits>

namespace voxc {
namespace {

using test::parseSymbolCell;
using test::parseTransformCell;

bool passes(const char* cell, float density) { return cellPasses(parseSymbolCell(cell), density, kMaterialNone); }

TEST(program_Ops, IgnPassesEverything) {
    for (float d : {0.0f, -1.0f, 1e30f, std::numeric_limits<float>::quiet_NaN()}) EXPECT_TRUE(passes("IGN", d));
}

TEST(program_Ops, PresIsStrictlyPositive) {
    EXPECT_TRUE(passes("PRES", 0.5f));
    EXPECT_TRUE(passes("PRES", std::numeric_limits<float>::denorm_min()));
    EXPECT_FALSE(passes("PRES", 0.0f));
    EXPECT_FALSE(passes("PRES", -0.0f));
    EXPECT_FALSE(passes("PRES", -0.1f));
}

TEST(program_Ops, AbsIsExactlyZero) {
    EXPECT_TRUE(passes("ABS", 0.0f));
    EXPECT_TRUE(passes("ABS", -0.0f));
    EXPECT_FALSE(passes("ABS", std::numeric_limits<float>::denorm_min()));
    EXPECT_FALSE(passes("ABS", -std::numeric_limits<float>::denorm_min()));
}

TEST(program_Ops, EqAndNeqCompareExactly) {
    const float v = 0.3f;
    const float next = std::nextafter(v, 1.0f);
    EXPECT_TRUE(passes("EQ 0.3", v));
    EXPECT_FALSE(passes("EQ 0.3", next));
    EXPECT_FALSE(passes("NEQ 0.3", v));
    EXPECT_TRUE(passes("NEQ 0.3", next));
    // 0.1 + 0.2 in float is not the float nearest 0.3: exact comparison sees the difference.
    const float sum = 0.1f + 0.2f;
    EXPECT_EQ(passes("EQ 0.3", sum), sum == 0.3f);
}

TEST(program_Ops, OrderingOperatorsAtTheirBoundary) {
    EXPECT_TRUE(passes("LT 1.0", 0.99f));
    EXPECT_FALSE(passes("LT 1.0", 1.0f));
    EXPECT_TRUE(passes("LEQ 1.0", 1.0f));
    EXPECT_FALSE(passes("LEQ 1.0", std::nextafter(1.0f, 2.0f)));
    EXPECT_FALSE(passes("GT 0.9", 0.9f));
    EXPECT_TRUE(passes("GT 0.9", std::nextafter(0.9f, 1.0f)));
    EXPECT_TRUE(passes("GEQ 0.8", 0.8f));
    EXPECT_FALSE(passes("GEQ 0.8", std::nextafter(0.8f, 0.0f)));
}

TEST(program_Ops, JoinedPredicatesMustAllPass) {
    EXPECT_TRUE(passes("LT 0.5 & GT 0.1", 0.3f));
    EXPECT_FALSE(passes("LT 0.5 & GT 0.1", 0.05f));
    EXPECT_FALSE(passes("LT 0.5 & GT 0.1", 0.6f));
    EXPECT_FALSE(passes("PRES & ABS", 0.0f));
}

TEST(program_Ops, NaNFailsEveryComparisonButNeq) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const char* cell : {"PRES", "ABS", "EQ 0", "LT 1", "LEQ 1", "GT 0", "GEQ 0"}) EXPECT_FALSE(passes(cell, nan)) << cell;
    EXPECT_TRUE(passes("NEQ 0", nan));
}

Grammar noClamp() { return Grammar{}; }

Grammar clamp01() {
    Grammar g;
    g.clampMin = 0.0f;
    g.clampMax = 1.0f;
    return g;
}

TEST(program_Ops, TransformsWithoutClamp) {
    const Grammar g = noClamp();
    EXPECT_EQ(applyTransform(parseTransformCell("NOP"), 0.7f, g), 0.7f);
    EXPECT_EQ(applyTransform(parseTransformCell("SET 0.5"), 0.7f, g), 0.5f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD 0.2"), 0.0f, g), 0.0f + 0.2f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD -0.2"), 0.5f, g), 0.5f - 0.2f);
    // No implicit clamp: densities may leave [0, 1].
    EXPECT_EQ(applyTransform(parseTransformCell("ADD 0.7"), 0.5f, g), 0.5f + 0.7f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD -0.7"), 0.5f, g), 0.5f - 0.7f);
    EXPECT_EQ(applyTransform(parseTransformCell("SET 3"), 0.0f, g), 3.0f);
}

TEST(program_Ops, ClampAppliesToWrittenValuesOnly) {
    const Grammar g = clamp01();
    EXPECT_EQ(applyTransform(parseTransformCell("ADD 0.7"), 0.5f, g), 1.0f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD -0.7"), 0.5f, g), 0.0f);
    EXPECT_EQ(applyTransform(parseTransformCell("SET 3"), 0.0f, g), 1.0f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD 0.2"), 0.5f, g), 0.5f + 0.2f);
    // NOP leaves the cell untouched, even outside the clamp range.
    EXPECT_EQ(applyTransform(parseTransformCell("NOP"), 2.5f, g), 2.5f);
    EXPECT_EQ(applyTransform(parseTransformCell("NOP"), -1.0f, g), -1.0f);
}

TEST(program_Ops, OneSidedClamp) {
    Grammar g;
    g.clampMin = 0.0f;
    EXPECT_EQ(applyTransform(parseTransformCell("ADD -1"), 0.5f, g), 0.0f);
    EXPECT_EQ(applyTransform(parseTransformCell("ADD 1"), 0.5f, g), 1.5f);
}

TEST(program_Ops, RegistryCoversEveryOperatorOnceWithArity) {
    const SymbolOp allSymbols[] = {SymbolOp::IGN, SymbolOp::PRES, SymbolOp::ABS, SymbolOp::EQ, SymbolOp::NEQ,
                                   SymbolOp::LT,  SymbolOp::LEQ,  SymbolOp::GT,  SymbolOp::GEQ};
    EXPECT_EQ(symbolOps().size(), std::size(allSymbols));
    for (SymbolOp op : allSymbols) {
        const SymbolOpInfo& info = symbolOpInfo(op);
        EXPECT_EQ(info.op, op);
        EXPECT_EQ(findSymbolOp(info.name), op);
        const bool valueless = op == SymbolOp::IGN || op == SymbolOp::PRES || op == SymbolOp::ABS;
        EXPECT_EQ(info.takesValue, !valueless) << info.name;
    }
    EXPECT_EQ(transformOps().size(), 3u);
    EXPECT_FALSE(transformOpInfo(TransformOp::NOP).takesValue);
    EXPECT_FALSE(transformOpInfo(TransformOp::NOP).writes);
    EXPECT_TRUE(transformOpInfo(TransformOp::SET).takesValue);
    EXPECT_TRUE(transformOpInfo(TransformOp::ADD).takesValue);
    EXPECT_EQ(findTransformOp("ADD"), TransformOp::ADD);
    EXPECT_FALSE(findSymbolOp("lt").has_value()); // names are case-sensitive
    EXPECT_FALSE(findTransformOp("MUL").has_value());
    EXPECT_FALSE(findSymbolOp("NOP").has_value());
    EXPECT_FALSE(findTransformOp("GEQ").has_value());
}

// One name per record across all three registries, and every record has every backend.
TEST(program_Ops, EveryRecordHasAUniqueNameAndEveryBackend) {
    std::set<std::string_view> names;
    for (const SymbolOpInfo& info : symbolOps()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(&symbolOpInfo(info.op), &info);
        EXPECT_FALSE(info.glsl("d", "0.5").empty());
        EXPECT_NE(info.accepts, nullptr);
    }
    for (const TransformOpInfo& info : transformOps()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_FALSE(info.glsl("d", "0.5").empty());
    }
    for (const MaterialOpInfo& info : materialOps()) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(&materialOpInfo(info.op), &info);
        EXPECT_EQ(findMaterialOp(info.name), info.op);
        EXPECT_FALSE(info.glsl("m", "3u").empty());
    }
    EXPECT_EQ(materialOps().size(), 2u);
}

TEST(program_Ops, MaterialTests) {
    EXPECT_TRUE(materialOpInfo(MaterialOp::MAT).eval(3, 3));
    EXPECT_FALSE(materialOpInfo(MaterialOp::MAT).eval(3, 4));
    EXPECT_TRUE(materialOpInfo(MaterialOp::NMAT).eval(3, 4));
    EXPECT_FALSE(materialOpInfo(MaterialOp::NMAT).eval(0, 0));
    EXPECT_EQ(materialOpInfo(MaterialOp::NMAT).glsl("m", "2u"), "(m != 2u)");
    // A cell passes when its density and material tests all pass.
    EXPECT_TRUE(cellPasses(parseSymbolCell("GEQ 0.5 & MAT 2"), 0.5f, 2));
    EXPECT_FALSE(cellPasses(parseSymbolCell("GEQ 0.5 & MAT 2"), 0.5f, 1));
    EXPECT_FALSE(cellPasses(parseSymbolCell("GEQ 0.5 & MAT 2"), 0.4f, 2));
    EXPECT_TRUE(cellPasses(parseSymbolCell("NMAT 0"), 0.0f, 7));
}

bool contains(const ValueSet& set, float d) {
    for (const ValueInterval& i : set.intervals()) {
        const bool aboveLo = d > i.lo || (d == i.lo && i.loClosed);
        const bool belowHi = d < i.hi || (d == i.hi && i.hiClosed);
        if (aboveLo && belowHi) return true;
    }
    return false;
}

// The checker's set semantics must agree with the interpreter's evaluation.
TEST(program_Ops, AcceptedSetAgreesWithEval) {
    const float values[] = {-1.0f, 0.0f, 0.3f, 1.0f};
    for (const SymbolOpInfo& info : symbolOps()) {
        for (float v : values) {
            const ValueSet accepted = info.accepts(v);
            for (float d : {-2.0f, -1.0f, -0.5f, -0.0f, 0.0f, 0.1f, 0.3f, std::nextafter(0.3f, 1.0f), 1.0f, 5.0f}) {
                EXPECT_EQ(contains(accepted, d), info.eval(d, v)) << info.name << " " << v << " density " << d;
            }
        }
    }
}

TEST(program_Ops, GlslEmission) {
    EXPECT_EQ(symbolOpInfo(SymbolOp::LT).glsl("d", "0.5"), "(d < 0.5)");
    EXPECT_EQ(symbolOpInfo(SymbolOp::ABS).glsl("d", ""), "(d == 0.0)");
    EXPECT_EQ(symbolOpInfo(SymbolOp::IGN).glsl("d", ""), "true");
    EXPECT_EQ(transformOpInfo(TransformOp::ADD).glsl("d", "0.2"), "(d + 0.2)");
    EXPECT_EQ(transformOpInfo(TransformOp::NOP).glsl("d", ""), "d");
    for (float v : {0.0f, 1.0f, 0.1f, -0.2f, 1e-7f, 3.4028235e38f, 1e-45f}) {
        const std::string text = glslFloat(v);
        EXPECT_EQ(std::strtof(text.c_str(), nullptr), v) << text;
        EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text; // a float literal, not an int
    }
}

} // namespace
} // namespace voxc

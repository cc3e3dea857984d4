// Each field pass is shown to fire on a small checked program: the IR before and after.
#include "voxc/builtins/Functions.h"
#include "voxc/check/Check.h"
#include "voxc/ir/Lower.h"
#include "voxc/ir/passes/EliminateCommonSubexpressions.h"
#include "voxc/ir/passes/FoldConstants.h"
#include "voxc/ir/passes/HoistColumnValues.h"
#include "voxc/ir/passes/RemoveDeadStages.h"

#include <gtest/gtest.h>

namespace voxc::ir {
namespace {

const std::string kHeader = "world { size = [8, 8, 8]; }\n"
                            "grammar g { rule r { size = [1, 1, 1]; symbol { [ABS] } transform { [SET 1] } } }\n";

// The module as lowering builds it, before any pass.
IrModule unoptimized(const std::string& text) {
    CheckResult result = checkSource(SourceFile("test.vox", kHeader + text));
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    IrModule first;
    bool captured = false;
    LowerOptions options;
    options.afterPass = [&](std::string_view, const IrModule& m) {
        if (!captured) first = m;
        captured = true;
    };
    if (result.program) lowerProgram(*result.program, options);
    return first;
}

size_t countKind(const IrField& field, FieldNode::Kind kind) {
    size_t n = 0;
    for (const FieldNode& node : field.nodes) n += node.kind == kind;
    return n;
}

const FieldNode& rootOf(const IrField& field) { return field.nodes.at(field.root); }

TEST(ir_RemoveDeadStages, EverythingBeforeTheLastSetIsDead) {
    const IrModule before = unoptimized("field a = 1; field b = 0.5; field c = y * 0.1;\n"
                                        "pipeline { start; g; set a; union c; set b; g; union c; }");
    EXPECT_EQ(before.pipeline.size(), 7u);
    const IrModule after = removeDeadStages(before);
    ASSERT_EQ(after.pipeline.size(), 3u);
    EXPECT_EQ(printStage(after.pipeline[0]), "set b");
    EXPECT_EQ(printStage(after.pipeline[1]), "g");
    EXPECT_EQ(printStage(after.pipeline[2]), "union c");
    ASSERT_EQ(after.deadStages.size(), 4u);
    EXPECT_EQ(printStage(after.deadStages[0]), "start");
    EXPECT_NE(printIr(after).find("dead stages start g set a union c\n"), std::string::npos) << printIr(after);
}

TEST(ir_RemoveDeadStages, KeepsEveryStageWithoutASet) {
    const IrModule before = unoptimized("field c = y * 0.1;\npipeline { start; g; union c; subtract c; intersect c; }");
    const IrModule after = removeDeadStages(before);
    EXPECT_EQ(after.pipeline.size(), 5u);
    EXPECT_TRUE(after.deadStages.empty());
}

TEST(ir_FoldConstants, FoldsExactRecordsOnly) {
    // vec3(1, 2, 3) * 2 folds (vec3 and mul are exact); sqrt is not exact on every device.
    const IrModule before = unoptimized("field f = dot(p, vec3(1, 2, 3) * 2) + sqrt(4);");
    const IrModule after = foldConstants(before);
    const IrField& field = after.fields.at(0);
    std::vector<glm::vec3> vectors;
    for (const FieldNode& node : field.nodes)
        if (node.kind == FieldNode::Kind::Constant && node.type == Type::Vec3) vectors.push_back(node.constant);
    // vec3(1, 2, 3) and its product (CSE then drops the first, now unused).
    EXPECT_EQ(vectors, (std::vector<glm::vec3>{{1, 2, 3}, {2, 4, 6}}));
    EXPECT_GT(countKind(field, FieldNode::Kind::Constant), countKind(before.fields[0], FieldNode::Kind::Constant));
    bool sqrtKept = false;
    for (const FieldNode& node : field.nodes)
        sqrtKept = sqrtKept || (node.kind == FieldNode::Kind::Call && functions()[node.function].name == "sqrt");
    EXPECT_TRUE(sqrtKept);
}

TEST(ir_FoldConstants, LeavesNonFiniteResultsToTheKernel) {
    const IrModule after = foldConstants(unoptimized("field f = x + clamp(vec2(1e38, 0).x * 1e38, 0, 1);"));
    size_t calls = countKind(after.fields.at(0), FieldNode::Kind::Call);
    EXPECT_EQ(calls, 3u); // add, clamp, and the overflowing mul
}

TEST(ir_EliminateCommonSubexpressions, MergesFoldedConstantsAndDropsUnusedNodes) {
    // vec2(1, 2).y folds to 2, equal to the literal 2 beside it.
    const IrModule folded = foldConstants(unoptimized("field f = (x + vec2(1, 2).y) * (x + 2);"));
    const IrField& before = folded.fields.at(0);
    const IrModule after = eliminateCommonSubexpressions(folded);
    const IrField& field = after.fields.at(0);
    EXPECT_LT(field.nodes.size(), before.nodes.size());
    // x, 2, x + 2, the product: one add serves both factors.
    EXPECT_EQ(field.nodes.size(), 4u) << printIr(after);
    const FieldNode& root = rootOf(field);
    ASSERT_EQ(root.operands.size(), 2u);
    EXPECT_EQ(root.operands[0], root.operands[1]);
    EXPECT_EQ(field.root, field.nodes.size() - 1);
}

TEST(ir_HoistColumnValues, MarksNodesThatDoNotDependOnY) {
    const IrModule after =
        hoistColumnValues(unoptimized("field f = fbm(vec3(wx, 0, wz) * 0.02, 3, 2.0, 0.5, 1) * 10 - wy + x;"));
    const IrField& field = after.fields.at(0);
    ASSERT_EQ(field.perColumn.size(), field.nodes.size());
    size_t hoisted = 0;
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        if (node.kind == FieldNode::Kind::Call && functions()[node.function].name == "fbm") {
            EXPECT_TRUE(field.perColumn[i]);
        }
        if (node.kind == FieldNode::Kind::Input && node.input == FieldInput::WorldY) {
            EXPECT_FALSE(field.perColumn[i]);
        }
        hoisted += field.perColumn[i];
    }
    EXPECT_FALSE(field.perColumn[field.root]);
    EXPECT_GE(hoisted, 6u);
    EXPECT_NE(printIr(after).find("call fbm("), std::string::npos);
}

} // namespace
} // namespace voxc::ir

// Field expressions through the checker: the Program::fields DAG (inputs, numbers, operators as
// registry calls, swizzles, let sharing, hash-consing, inlining), field stages, and the errors.
#include "CheckTestUtil.h"

#include "voxc/builtins/Functions.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace voxc {
namespace field_check_test {

using test::check;
using test::codes;

const std::string kWorld = "world { size = [8, 8, 8]; }\n";

Field onlyField(const std::string& declarations) {
    CheckResult result = check(kWorld + declarations);
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    if (!result.program || result.program->fields.empty()) return {};
    return result.program->fields.back();
}

std::string functionName(const FieldNode& node) { return std::string(functions()[node.function].name); }

const FieldNode& root(const Field& f) { return f.nodes.at(f.root); }

// A node written out as an expression, e.g. "sub(1, abs(x))".
std::string written(const Field& f, uint32_t index) {
    const FieldNode& node = f.nodes.at(index);
    switch (node.kind) {
    case FieldNode::Kind::Constant: return std::to_string(node.constant.x) + "/" + std::to_string(node.constantInt);
    case FieldNode::Kind::Input: return "in" + std::to_string(int(node.input));
    case FieldNode::Kind::Component: return written(f, node.operands[0]) + "." + std::to_string(node.component);
    case FieldNode::Kind::Call: break;
    case FieldNode::Kind::PointSet: return "point_set(" + written(f, node.operands[0]) + ")";
    case FieldNode::Kind::Map:
        return node.map->name + "(" + written(f, node.operands[0]) + ", " + written(f, node.operands[1]) + ")";
    }
    std::string text = functionName(node) + "(";
    for (size_t i = 0; i < node.operands.size(); ++i) text += (i ? ", " : "") + written(f, node.operands[i]);
    return text + ")";
}

TEST(check_Fields, InputsNumbersAndOperatorsBecomeNodes) {
    const Field f = onlyField("field f = x + wy * 2.5;");
    ASSERT_EQ(f.nodes.size(), 5u);
    EXPECT_EQ(f.root, 4u);
    const FieldNode& add = root(f);
    EXPECT_EQ(add.kind, FieldNode::Kind::Call);
    EXPECT_EQ(functionName(add), "add");
    EXPECT_EQ(add.type, Type::Float);
    const FieldNode& x = f.nodes[add.operands[0]];
    EXPECT_EQ(x.kind, FieldNode::Kind::Input);
    EXPECT_EQ(x.input, FieldInput::LocalX);
    const FieldNode& mul = f.nodes[add.operands[1]];
    EXPECT_EQ(functionName(mul), "mul");
    EXPECT_EQ(f.nodes[mul.operands[0]].input, FieldInput::WorldY);
    EXPECT_EQ(f.nodes[mul.operands[1]].kind, FieldNode::Kind::Constant);
    EXPECT_EQ(f.nodes[mul.operands[1]].constant.x, 2.5f);
    // Operands always precede their users.
    for (uint32_t i = 0; i < f.nodes.size(); ++i)
        for (uint32_t operand : f.nodes[i].operands) EXPECT_LT(operand, i);
}

TEST(check_Fields, NumbersFoldAndBecomeIntsWhereTheRuleWantsInts) {
    const Field f = onlyField("const S = 3;\nfield f = fbm(p * 0.5, 2 + 3, 2, 0.5, S * 2) - 1 / 4;");
    const FieldNode& sub = root(f);
    EXPECT_EQ(functionName(sub), "sub");
    EXPECT_EQ(f.nodes[sub.operands[1]].constant.x, 0.25f); // folded like a const
    const FieldNode& fbm = f.nodes[sub.operands[0]];
    ASSERT_EQ(functionName(fbm), "fbm");
    const Type expected[] = {Type::Vec3, Type::Int, Type::Float, Type::Float, Type::Int};
    for (size_t i = 0; i < 5; ++i) EXPECT_EQ(f.nodes[fbm.operands[i]].type, expected[i]) << i;
    EXPECT_EQ(f.nodes[fbm.operands[1]].constantInt, 5);
    EXPECT_EQ(f.nodes[fbm.operands[2]].constant.x, 2.0f);
    EXPECT_EQ(f.nodes[fbm.operands[4]].constantInt, 6);
    // `p` is vec3(x, y, z).
    const FieldNode& scaled = f.nodes[fbm.operands[0]];
    const FieldNode& p = f.nodes[scaled.operands[0]];
    EXPECT_EQ(functionName(p), "vec3");
    EXPECT_EQ(f.nodes[p.operands[2]].input, FieldInput::LocalZ);
}

TEST(check_Fields, LetIsOneSharedNodeAndEqualSubexpressionsAreShared) {
    const Field let = onlyField("field f = let h = sin(x) in h * h;");
    EXPECT_EQ(let.nodes.size(), 3u); // x, sin, mul
    EXPECT_EQ(root(let).operands[0], root(let).operands[1]);
    const Field repeated = onlyField("field f = sin(x) * sin(x) + 1 + (1 + 0);");
    EXPECT_EQ(repeated.nodes.size(), 6u); // x, sin, mul, 1, add, add: one sin(x), one constant 1
    // An unused binding leaves no node behind.
    EXPECT_EQ(onlyField("field f = let unused = cos(y) in x;").nodes.size(), 1u);
}

TEST(check_Fields, UserFunctionsAreInlined) {
    const Field called = onlyField("fn ridge(v: float, k: float) -> float = k - abs(v);\nfield f = ridge(x, 1);");
    const Field inline_ = onlyField("field f = 1 - abs(x);");
    EXPECT_EQ(called.nodes.size(), inline_.nodes.size());
    EXPECT_EQ(written(called, called.root), written(inline_, inline_.root));
    // Functions may call each other in any declaration order; int parameters take int numbers.
    const Field nested = onlyField("fn a(q: vec3) -> float = b(q, 7);\nfn b(q: vec3, s: int) -> float = perlin3(q, s);\n"
                                   "field f = a(wp);");
    EXPECT_EQ(functionName(root(nested)), "perlin3");
    EXPECT_EQ(nested.nodes[root(nested).operands[1]].constantInt, 7);
}

TEST(check_Fields, SwizzlesConditionalsAndLogic) {
    const Field one = onlyField("field f = p.y;");
    EXPECT_EQ(root(one).kind, FieldNode::Kind::Component);
    EXPECT_EQ(root(one).component, 1u);
    const Field two = onlyField("field f = length(wp.zx);");
    const FieldNode& vec2 = two.nodes[root(two).operands[0]];
    EXPECT_EQ(functionName(vec2), "vec2");
    EXPECT_EQ(two.nodes[vec2.operands[0]].component, 2u);
    EXPECT_EQ(two.nodes[vec2.operands[1]].component, 0u);
    const Field conditional = onlyField("field f = x < 3 && !(y >= 2) || z == 1 ? 1 : 0;");
    const FieldNode& select = root(conditional);
    EXPECT_EQ(functionName(select), "select");
    EXPECT_EQ(functionName(conditional.nodes[select.operands[0]]), "or");
    EXPECT_EQ(conditional.nodes[select.operands[0]].type, Type::Bool);
}

TEST(check_Fields, FieldStagesInThePipeline) {
    CheckResult result = check(kWorld + "field a = 1;\nfield b = x;\n"
                                        "grammar g { rule r { size = [1, 1, 1]; symbol { [IGN] } transform { [NOP] } } }\n"
                                        "pipeline { start; set b; g; union a; subtract b; intersect a; }");
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<Stage>& stages = result.program->pipeline;
    ASSERT_EQ(stages.size(), 6u);
    EXPECT_EQ(stages[1].kind, Stage::Kind::Field);
    EXPECT_EQ(stages[1].index, 1u);
    EXPECT_EQ(stages[1].mode, FieldMode::Set);
    EXPECT_EQ(stages[2].kind, Stage::Kind::Grammar);
    EXPECT_EQ(stages[3].mode, FieldMode::Union);
    EXPECT_EQ(stages[4].mode, FieldMode::Subtract);
    EXPECT_EQ(stages[5].mode, FieldMode::Intersect);
    EXPECT_EQ(stages[5].index, 0u);
    // Without a pipeline block, fields are declared but do not run.
    CheckResult implicit = check(kWorld + "field a = 1;");
    ASSERT_TRUE(implicit.program);
    EXPECT_EQ(implicit.program->pipeline.size(), 1u);
}

struct ErrorCase {
    std::string text;
    std::vector<std::string> codes;
};

TEST(check_Fields, ErrorsAreLocatedAndCoded) {
    const ErrorCase cases[] = {
        {"field f = nosie;", {"E0002"}},
        {"field f = perlin4(p, 1);", {"E0002"}},
        {"fn g(v: float) -> float = v + x;\nfield f = 1;", {"E0002"}},
        {"field f = p + 1;", {"E0010"}},                  // the root must be a float
        {"field f = p * vec2(1, 2);", {"E0010"}},         // operator types
        {"field f = perlin3(p, 0.5);", {"E0010"}},        // 0.5 is not an int
        {"field f = x.y;", {"E0010"}},                    // swizzle of a float
        {"field f = vec2(x, y).z;", {"E0010"}},           // no z in a vec2
        {"fn g(v: float) -> vec3 = v;\nfield f = 1;", {"E0010"}},
        {"fn g(v: float) -> float = v;\nfield f = g(p);", {"E0010"}},
        {"fn g(v: float) -> float = v;\nfield f = g(1, 2);", {"E0006"}},
        {"fn g(v: float) -> float = h(v);\nfn h(v: float) -> float = g(v);\nfield f = 1;", {"E0013", "E0013"}},
        {"fn g(v: flot) -> float = v;\nfield f = 1;", {"E0002"}},
        {"fn min(v: float) -> float = v;\nfield f = 1;", {"E0003"}},
        {"field f = 1;\nfield f = 2;", {"E0003"}},
        {"field f = 1 / 0;", {"E0007"}},
        {"field f = 1;\npipeline { start; add f; }", {"E0011"}},
        {"field f = 1;\npipeline { start; f; }", {"E0009"}},
        {"field f = 1;\npipeline { start; set g; }", {"E0002"}},
    };
    for (const ErrorCase& c : cases) {
        CheckResult result = check(kWorld + c.text);
        EXPECT_EQ(codes(result), c.codes) << c.text << "\n" << result.rendered();
        for (const Diagnostic& d : result.diagnostics) EXPECT_GT(d.loc.line, 0u) << c.text;
    }
}

// The wrong argument is the culprit: the caret is on it, and a note quotes the signature.
TEST(check_Fields, TypeErrorsQuoteTheSignature) {
    CheckResult result = check(kWorld + "field f = perlin3(x, 1);");
    ASSERT_EQ(result.diagnostics.size(), 1u);
    const Diagnostic& d = result.diagnostics[0];
    EXPECT_NE(d.message.find("argument 1"), std::string::npos) << d.message;
    EXPECT_EQ(d.loc.line, 2u);
    EXPECT_EQ(d.loc.column, 19u) << "at `x`, the first argument";
    const std::string signature(findFunction("perlin3")->signature);
    EXPECT_TRUE(std::any_of(d.notes.begin(), d.notes.end(), [&](const DiagnosticNote& note) {
        return note.message.find(signature) != std::string::npos;
    })) << "no note quotes " << signature;
}

} // namespace field_check_test
} // namespace voxc

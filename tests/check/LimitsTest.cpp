// The checker's bounds: inlining by sharing (work, DAG size and depth) and numbers beyond the
// float or double range, each asserting the code and where it is reported.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace voxc {
namespace limits_test {

using test::check;
using test::codes;

const std::string kWorld = "world { size = [8, 8, 8]; }\n";

CheckResult checkWith(const std::string& text, const Limits& limits) {
    return checkSource(SourceFile("test.vox", text), limits);
}

// f0 .. f<count-1>, each calling the previous one twice with the same argument: inlined by
// copying, lowering f<count-1> would visit 2^count bodies.
std::string doublingChain(int count) {
    std::string text = "fn f0(v: float) -> float = v * 0.5 + 1;\n";
    for (int i = 1; i < count; ++i)
        text += "fn f" + std::to_string(i) + "(v: float) -> float = f" + std::to_string(i - 1) + "(v) + f" +
                std::to_string(i - 1) + "(v);\n";
    return text + "field g = f" + std::to_string(count - 1) + "(x);\n";
}

// Sharing makes the 41-function chain cost linear work: a step budget of a few thousand
// expression nodes (2^41 without sharing) is enough, and the DAG holds one add per function.
TEST(check_Limits, InliningByShareCostsLinearWork) {
    Limits limits;
    limits.maxLoweringSteps = 2000;
    CheckResult result = checkWith(kWorld + doublingChain(41), limits);
    ASSERT_FALSE(result.hasErrors()) << result.rendered();
    EXPECT_LE(result.program->fields.at(0).nodes.size(), 41u + 4u);
}

// Each call of f9 with a new argument lowers its ten bodies again (about 60 nodes), so the
// functions pass a budget of 100 nodes on their own but the field's two calls do not.
TEST(check_Limits, LoweringStepsAreCappedAtTheField) {
    Limits limits;
    limits.maxLoweringSteps = 100;
    std::string chain = doublingChain(10);
    EXPECT_FALSE(checkWith(kWorld + chain, limits).hasErrors());
    chain.replace(chain.find("field g = f9(x);"), std::string::npos, "field g = f9(x) + f9(x + 1);\n");
    CheckResult result = checkWith(kWorld + chain, limits);
    ASSERT_EQ(codes(result), std::vector<std::string>{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 12u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 7u);
    EXPECT_NE(result.diagnostics[0].message.find("field 'g' is too large to inline"), std::string::npos);
}

// f<k>(v) = f<k-1>(f<k-1>(v)): the DAG is 2^k deep while the calls nest only k deep.
std::string squaringChain(int count) {
    std::string text = "fn f0(v: float) -> float = v + 1;\n";
    for (int i = 1; i < count; ++i)
        text += "fn f" + std::to_string(i) + "(v: float) -> float = f" + std::to_string(i - 1) + "(f" +
                std::to_string(i - 1) + "(v));\n";
    return text + "field g = f" + std::to_string(count - 1) + "(x);\n";
}

TEST(check_Limits, DagDepthIsCappedAtTheField) {
    // 2^10 adds and the input: 1025 levels, one past the limit; 2^9 + 1 fits.
    EXPECT_FALSE(check(kWorld + squaringChain(10)).hasErrors());
    CheckResult result = check(kWorld + squaringChain(11));
    ASSERT_EQ(codes(result), std::vector<std::string>{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 13u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 7u);
    EXPECT_NE(result.diagnostics[0].message.find("nests 1025 operations deep"), std::string::npos);
}

TEST(check_Limits, DagSizeIsCappedAtTheField) {
    Limits limits;
    limits.maxFieldNodes = 40;
    CheckResult result = checkWith(kWorld + squaringChain(6), limits); // 2^5 adds, an input, a constant
    ASSERT_FALSE(result.hasErrors()) << result.rendered();
    result = checkWith(kWorld + squaringChain(7), limits);
    ASSERT_EQ(codes(result), std::vector<std::string>{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 9u);
    EXPECT_NE(result.diagnostics[0].message.find("field 'g' has 66 nodes"), std::string::npos);
}

// Through inlined calls an expression nests deeper than its text: the field's call of the
// identity chain below is one level and each function body one more.
TEST(check_Limits, ExpressionDepthThroughCallsIsCapped) {
    auto identityChain = [](int count) {
        std::string text = "fn f0(v: float) -> float = v;\n";
        for (int i = 1; i < count; ++i)
            text += "fn f" + std::to_string(i) + "(v: float) -> float = f" + std::to_string(i - 1) + "(v);\n";
        return text + "field g = f" + std::to_string(count - 1) + "(x);\n";
    };
    Limits limits;
    limits.maxFieldDepth = 20;
    EXPECT_FALSE(checkWith(kWorld + identityChain(19), limits).hasErrors());
    CheckResult result = checkWith(kWorld + identityChain(20), limits);
    ASSERT_FALSE(result.diagnostics.empty());
    const Diagnostic& last = result.diagnostics.back();
    EXPECT_EQ(last.code, "E0012");
    // f1's argument in `f0(v)`, lowered before f0's body, is the first node 20 levels down.
    EXPECT_EQ(last.loc.line, 3u);
    EXPECT_EQ(last.loc.column, 31u);
    EXPECT_NE(last.message.find("(through f19 -> f18"), std::string::npos) << last.message;
}

// `fn f(p0: float, ...) -> float = p0;` called with x for every parameter.
std::string manyParameters(int count) {
    std::string parameters, arguments;
    for (int i = 0; i < count; ++i) {
        parameters += (i ? ", p" : "p") + std::to_string(i) + ": float";
        arguments += i ? ", x" : "x";
    }
    return kWorld + "fn f(" + parameters + ") -> float = p0;\nfield g = f(" + arguments + ");\n";
}

TEST(check_Limits, FunctionParametersAreCapped) {
    EXPECT_FALSE(check(manyParameters(64)).hasErrors());
    CheckResult result = check(manyParameters(65));
    ASSERT_EQ(codes(result), std::vector<std::string>{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 4u);
    EXPECT_NE(result.diagnostics[0].message.find("65 parameters"), std::string::npos);
}

struct OutOfRange {
    const char* what;
    std::string text;
    uint32_t line;
    uint32_t column;
};

// Every place a number can be written, with a literal beyond the double (or float) range.
TEST(check_Limits, NumbersBeyondTheRangeAreE0007Everywhere) {
    const OutOfRange cases[] = {
        {"const", kWorld + "const a = 1e999;\n", 2, 11},
        {"folded const", kWorld + "const a = 1e300 * 1e300;\n", 2, 11},
        {"world key", "world { size = [8, 8, 8]; seed = 1e999; }\n", 1, 34},
        {"list element", "world { size = [8, 1e400, 8]; }\n", 1, 20},
        {"fill value", kWorld + "start { fill { value = 1e999; } }\n", 2, 24},
        {"sphere radius", kWorld + "start { sphere { center = [4, 4, 4]; radius = 1e400; } }\n", 2, 47},
        {"grammar cell", test::oneRule("[1, 1, 1]", "[GEQ 1e999]", "[SET 1]"), 7, 19},
        {"cell beyond float", test::oneRule("[1, 1, 1]", "[GEQ 1e39]", "[SET 1]"), 7, 19},
        {"clamp bound", test::oneRule("[1, 1, 1]", "[GEQ 0.5]", "[SET 1]", "", "clamp = [-1e39, 1];"), 3, 10},
        {"field literal", kWorld + "field f = x + 1e400;\n", 2, 15},
        {"field beyond float", kWorld + "field f = x + 1e39;\n", 2, 11},
        {"field folded", kWorld + "field f = x + 1e300 * 1e300;\n", 2, 15},
        {"function body", kWorld + "fn g(v: float) -> float = v * 1e999;\nfield f = g(x);\n", 2, 31},
        {"feature key", kWorld + "feature a = arch { start = [1e999, 16, 16]; }\n", 2, 29},
    };
    for (const OutOfRange& c : cases) {
        SCOPED_TRACE(c.what);
        CheckResult result = check(c.text);
        ASSERT_FALSE(result.diagnostics.empty()) << c.text;
        const Diagnostic& first = result.diagnostics[0];
        EXPECT_EQ(first.code, "E0007") << result.rendered();
        EXPECT_EQ(first.loc.line, c.line) << result.rendered();
        EXPECT_EQ(first.loc.column, c.column) << result.rendered();
    }
}

// `voxc explore` replaces constants by value; a NaN would pass every range check.
TEST(check_Limits, NonFiniteConstantOverridesAreE0007) {
    for (double value : {std::nan(""), std::numeric_limits<double>::infinity()}) {
        CheckOptions options;
        options.constOverrides["R"] = value;
        const std::string text = "const R = 1;\n" + kWorld + "field f = x * R;\n";
        CheckResult result = checkSource(SourceFile("t.vox", text), options);
        ASSERT_EQ(codes(result), std::vector<std::string>{"E0007"}) << result.rendered();
        EXPECT_EQ(result.diagnostics[0].loc.line, 1u);
        EXPECT_EQ(result.diagnostics[0].loc.column, 7u);
    }
}

} // namespace limits_test
} // namespace voxc

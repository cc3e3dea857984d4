// The front end's bounds on its input: source size and nesting depth. Each construct is tested
// at the deepest nesting the limit allows and one level past it, where parsing must stop with
// one E0012 located at the token that passes the limit (never a stack overflow).
#include "voxc/syntax/Parser.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace voxc {
namespace {

std::string repeat(std::string_view text, size_t count) {
    std::string out;
    out.reserve(text.size() * count);
    for (size_t i = 0; i < count; ++i) out += text;
    return out;
}

std::vector<Diagnostic> parseErrors(const std::string& text) {
    Diagnostics diagnostics;
    parse(SourceFile("t.vox", text), diagnostics);
    return diagnostics.take();
}

// A construct nested `levels` deep. `column` is where line 1 holds the first token of the
// first rule that lies too deep when `levels` is one past what the limit allows.
struct Nested {
    std::string text;
    uint32_t column;
};

using Builder = Nested (*)(size_t levels);

// The operand after the last opener passes the limit.
Nested parens(size_t levels) {
    return {"const a = " + repeat("(", levels) + "1" + repeat(")", levels) + ";", uint32_t(11 + levels)};
}
Nested negations(size_t levels) { return {"const a = " + repeat("-", levels) + "1;", uint32_t(11 + levels)}; }
Nested fieldParens(size_t levels) {
    return {"field f = " + repeat("(", levels) + "x" + repeat(")", levels) + ";", uint32_t(11 + levels)};
}
Nested fieldUnary(size_t levels) { return {"field f = " + repeat("!", levels) + "x;", uint32_t(11 + levels)}; }
// Calls nest a level per call: `abs(abs(x))`.
Nested calls(size_t levels) {
    return {"field f = " + repeat("abs(", levels) + "x" + repeat(")", levels) + ";", uint32_t(11 + 4 * levels)};
}
// `.x` chains left-associatively: `x.x.x` is reported at its first operand.
Nested swizzles(size_t levels) { return {"field f = x" + repeat(".x", levels) + ";", 11}; }
// Each `let v = 1 in ` is 13 characters; the innermost let's value passes the limit.
Nested lets(size_t levels) {
    return {"field f = " + repeat("let v = 1 in ", levels) + "v;", uint32_t(11 + 13 * (levels - 1) + 8)};
}
// Each `x ? 1 : ` nests its else-branch one level deeper; `?` wraps the innermost condition in
// a context one level too deep, reported at that condition.
Nested conditionals(size_t levels) {
    return {"field f = " + repeat("x ? 1 : ", levels) + "0;", uint32_t(11 + 8 * (levels - 1))};
}
// `b { k = [[[1]]]; }`: the number inside passes the limit.
Nested lists(size_t levels) {
    return {"b { k = " + repeat("[", levels) + "1" + repeat("]", levels) + "; }", uint32_t(9 + levels)};
}
// Each `b { ` is 4 characters; the innermost block's kind word passes the limit.
Nested blocks(size_t levels) {
    return {repeat("b { ", levels) + repeat("} ", levels), uint32_t(1 + 4 * (levels - 1))};
}

struct Construct {
    const char* name;
    Builder build;
    size_t deepestAllowed; // levels of the construct at exactly kDefaultMaxNesting
};

// Levels of the parse tree (kDefaultMaxNesting = 256) besides the construct's own:
const Construct kConstructs[] = {
    // file, item, declaration, and the innermost operand: 256 - 4.
    {"parentheses", parens, 252},
    {"negations", negations, 252},
    {"field parentheses", fieldParens, 252},
    {"field unary operators", fieldUnary, 252},
    {"calls", calls, 252},
    {"swizzles", swizzles, 252},
    {"let chains", lets, 252},
    {"conditional chains", conditionals, 252},
    // file, item, block, member, assignment, then the number's value and expression: 256 - 7.
    {"lists", lists, 249},
    // file, then two levels per block (item or member, and the block): (256 - 1) / 2.
    {"blocks", blocks, 127},
};

TEST(syntax_Limits, EveryConstructNestsToTheLimitAndNoFurther) {
    for (const Construct& construct : kConstructs) {
        SCOPED_TRACE(construct.name);
        EXPECT_TRUE(parseErrors(construct.build(construct.deepestAllowed).text).empty());
        Nested tooDeep = construct.build(construct.deepestAllowed + 1);
        std::vector<Diagnostic> errors = parseErrors(tooDeep.text);
        ASSERT_EQ(errors.size(), 1u);
        EXPECT_EQ(errors[0].code, "E0012");
        EXPECT_EQ(errors[0].loc.line, 1u);
        EXPECT_EQ(errors[0].loc.column, tooDeep.column);
        EXPECT_NE(errors[0].message.find("256"), std::string::npos);
    }
}

TEST(syntax_Limits, FiftyThousandParenthesesStopAtTheLimit) {
    std::vector<Diagnostic> errors = parseErrors(parens(50000).text);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].code, "E0012");
    EXPECT_EQ(errors[0].loc.column, parens(253).column);
}

// A left-associative chain parses in a loop but builds one tree level per operator: the chain
// is reported at its first operand, where the too-deep part of the tree starts.
TEST(syntax_Limits, LongOperatorChainsAreBoundedByDepth) {
    // file, item, fieldDecl, then one level per `+`, then the first operand: 256 - 4 = 252.
    auto chain = [](size_t operators) { return "field f = x" + repeat(" + x", operators) + ";"; };
    EXPECT_TRUE(parseErrors(chain(252)).empty());
    std::vector<Diagnostic> errors = parseErrors(chain(253));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].code, "E0012");
    EXPECT_EQ(errors[0].loc.column, 11u);

    errors = parseErrors(chain(20000));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].code, "E0012");
    EXPECT_EQ(errors[0].loc.column, 11u);
}

// Garbage stops the parse once the errors pass the cap (the lexer would otherwise raise one
// exception per byte): the first 20 errors and the "too many errors" line.
TEST(syntax_Limits, GarbageStopsAtTheErrorCap) {
    for (const std::string& garbage : {repeat("@", 100000), repeat("] ", 100000)}) {
        std::vector<Diagnostic> errors = parseErrors(garbage);
        ASSERT_FALSE(errors.empty());
        EXPECT_EQ(errors.front().code, "E0001");
        EXPECT_EQ(errors.front().loc.column, 1u);
        if (garbage[0] == '@') {
            ASSERT_EQ(errors.size(), size_t(Diagnostics::kMaxErrors) + 1);
            EXPECT_EQ(errors.back().code, "");
        }
    }
}

TEST(syntax_Limits, ACustomLimitApplies) {
    Diagnostics diagnostics;
    parse(SourceFile("t.vox", parens(9).text), diagnostics, 13);
    EXPECT_FALSE(diagnostics.hasErrors());
    parse(SourceFile("t.vox", parens(10).text), diagnostics, 13);
    ASSERT_EQ(diagnostics.all().size(), 1u);
    EXPECT_EQ(diagnostics.all()[0].code, "E0012");
}

TEST(syntax_Limits, OversizedSourcesStopAtTheCap) {
    const std::string path = testing::TempDir() + "/voxc_oversized.vox";
    {
        std::ofstream out(path, std::ios::binary);
        out << std::string(1001, ' ');
    }
    Diagnostics diagnostics;
    EXPECT_FALSE(loadSourceFile(path, diagnostics, 1000));
    ASSERT_EQ(diagnostics.all().size(), 1u);
    EXPECT_EQ(diagnostics.all()[0].code, "E0012");
    EXPECT_EQ(diagnostics.all()[0].loc.line, 0u);
    EXPECT_NE(diagnostics.all()[0].message.find("1000 bytes"), std::string::npos);

    // Exactly at the cap is fine.
    std::filesystem::resize_file(path, 1000);
    std::optional<SourceFile> atCap = loadSourceFile(path, diagnostics, 1000);
    ASSERT_TRUE(atCap);
    EXPECT_EQ(atCap->text().size(), 1000u);
    std::filesystem::remove(path);
}

// A device never ends: reading stops one byte past the cap instead of exhausting memory.
TEST(syntax_Limits, EndlessDevicesStopAtTheCap) {
    Diagnostics diagnostics;
    EXPECT_FALSE(loadSourceFile("/dev/zero", diagnostics));
    ASSERT_EQ(diagnostics.all().size(), 1u);
    EXPECT_EQ(diagnostics.all()[0].code, "E0012");
    EXPECT_NE(diagnostics.all()[0].message.find("4 MiB"), std::string::npos);
}

} // namespace
} // namespace voxc

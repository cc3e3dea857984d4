#include "voxc/syntax/Parser.h"

#include <gtest/gtest.h>

#include <limits>

namespace voxc {
namespace {

struct Parsed {
    ast::File file;
    std::vector<Diagnostic> diagnostics;
};

Parsed parseText(const std::string& text) {
    Diagnostics diagnostics;
    ast::File file = parse(SourceFile("t.vox", text), diagnostics);
    return {std::move(file), diagnostics.take()};
}

TEST(syntax_Parser, BuildsBlocksWithLocations) {
    Parsed parsed = parseText("const K = 2;\n"
                              "grammar caves {\n"
                              "  stride = [1, K, 1];\n"
                              "  rule r { symbol { [GEQ 0.5 & LT 1, IGN] } }\n"
                              "}\n"
                              "pipeline { start; caves; }\n");
    ASSERT_TRUE(parsed.diagnostics.empty());
    ASSERT_EQ(parsed.file.constants.size(), 1u);
    EXPECT_EQ(parsed.file.constants[0].name, "K");
    EXPECT_EQ(parsed.file.constants[0].loc.column, 7u);
    ASSERT_EQ(parsed.file.blocks.size(), 2u);

    const ast::Block& grammar = parsed.file.blocks[0];
    EXPECT_EQ(grammar.kind, "grammar");
    EXPECT_EQ(grammar.label, "caves");
    EXPECT_EQ(grammar.loc.line, 2u);
    EXPECT_EQ(grammar.loc.length, 7u);
    ASSERT_EQ(grammar.assignments.size(), 1u);
    const ast::Value& stride = grammar.assignments[0].value;
    ASSERT_TRUE(stride.isList());
    ASSERT_EQ(stride.elements.size(), 3u);
    EXPECT_EQ(stride.elements[1].scalar->kind, ast::Expr::Kind::Name);
    EXPECT_EQ(stride.loc.column, 12u);

    const ast::Block& symbol = grammar.blocks.at(0).blocks.at(0);
    EXPECT_EQ(symbol.kind, "symbol");
    ASSERT_EQ(symbol.rows.size(), 1u);
    const ast::Row& row = symbol.rows[0];
    ASSERT_EQ(row.cells.size(), 2u);
    ASSERT_EQ(row.cells[0].terms.size(), 2u);
    EXPECT_EQ(row.cells[0].terms[0].op, "GEQ");
    EXPECT_EQ(row.cells[0].terms[0].value->number, 0.5);
    EXPECT_EQ(row.cells[0].terms[1].op, "LT");
    EXPECT_EQ(row.cells[1].terms[0].value, nullptr);
    EXPECT_EQ(row.cells[1].loc.column, 38u);

    const ast::Block& pipeline = parsed.file.blocks[1];
    ASSERT_EQ(pipeline.names.size(), 2u);
    EXPECT_EQ(pipeline.names[1].name, "caves");
}

TEST(syntax_Parser, ExpressionPrecedence) {
    Parsed parsed = parseText("const X = -1 + 2 * (3 - 4) / 5;");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const ast::Expr& add = *parsed.file.constants.at(0).value;
    ASSERT_EQ(add.kind, ast::Expr::Kind::Add);
    EXPECT_EQ(add.lhs->kind, ast::Expr::Kind::Negate);
    ASSERT_EQ(add.rhs->kind, ast::Expr::Kind::Divide);
    EXPECT_EQ(add.rhs->lhs->kind, ast::Expr::Kind::Multiply);
    EXPECT_EQ(add.rhs->lhs->rhs->kind, ast::Expr::Kind::Subtract); // parentheses leave no node
}

TEST(syntax_Parser, NumberForms) {
    Parsed parsed = parseText("const A = 1.5e3; const B = .25; const C = 7.;");
    ASSERT_TRUE(parsed.diagnostics.empty());
    EXPECT_EQ(parsed.file.constants[0].value->number, 1500.0);
    EXPECT_EQ(parsed.file.constants[1].value->number, 0.25);
    EXPECT_EQ(parsed.file.constants[2].value->number, 7.0);
}

// Beyond the double range a literal is infinite, for the checker to report (E0007), never the
// zero that a failed conversion leaves; below it, a literal is zero.
TEST(syntax_Parser, NumbersBeyondTheDoubleRange) {
    Parsed parsed = parseText("const A = 1e999; const B = 123456.7e305; const C = 0.00001e309; const D = 1e-999;"
                              "const E = 0.0e999; const F = 1e99999999999999999999; field f = 1e400;");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(parsed.file.constants[0].value->number, inf);
    EXPECT_EQ(parsed.file.constants[1].value->number, inf);
    EXPECT_EQ(parsed.file.constants[2].value->number, 1e304);
    EXPECT_EQ(parsed.file.constants[3].value->number, 0.0);
    EXPECT_EQ(parsed.file.constants[4].value->number, 0.0);
    EXPECT_EQ(parsed.file.constants[5].value->number, inf);
    EXPECT_EQ(parsed.file.fields[0].value->number, inf);
}

TEST(syntax_Parser, CommentsAreSkipped) {
    Parsed parsed = parseText("// line\n/* block\n spanning */ world { /* inner */ size = [1, 1, 1]; }");
    EXPECT_TRUE(parsed.diagnostics.empty());
    EXPECT_EQ(parsed.file.blocks.at(0).loc.line, 3u);
}

TEST(syntax_Parser, RecoversAndReportsSeveralErrors) {
    Parsed parsed = parseText("world {\n"
                              "  size = [8, 8, 8]\n"          // missing ';'
                              "  seed = ;\n"                  // missing value
                              "}\n"
                              "grammar g { rule r { symbol { [PRES, } } }\n" // missing cell
                              "start { box { min = [0, 0, 0]; } }\n");
    ASSERT_EQ(parsed.diagnostics.size(), 3u);
    for (const Diagnostic& d : parsed.diagnostics) EXPECT_EQ(d.code, "E0001");
    EXPECT_EQ(parsed.diagnostics[0].message, "expected ';'");
    EXPECT_EQ(parsed.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(parsed.diagnostics[0].loc.column, 19u); // just after ']'
    EXPECT_EQ(parsed.diagnostics[1].loc.line, 3u);
    EXPECT_EQ(parsed.diagnostics[2].loc.line, 5u);
    // Recovery keeps the blocks after the errors.
    EXPECT_EQ(parsed.file.blocks.back().kind, "start");
}

TEST(syntax_Parser, ReadableMessages) {
    EXPECT_EQ(parseText("world { size = [1, 2 }").diagnostics.at(0).message, "expected ',' or ']', found '}'");
    EXPECT_EQ(parseText("world { size = 1; ").diagnostics.at(0).message,
              "expected '}', '[', a name or a string, found end of file");
    EXPECT_EQ(parseText("world { size ~ 1; }").diagnostics.at(0).message, "unexpected character '~'");
    Parsed comment = parseText("world { }\n/* open");
    ASSERT_EQ(comment.diagnostics.size(), 1u);
    EXPECT_EQ(comment.diagnostics[0].loc.line, 2u);
    EXPECT_NE(comment.diagnostics[0].message.find("unterminated block comment"), std::string::npos);
}

TEST(syntax_Parser, PipelineStagesTakeAClause) {
    Parsed parsed = parseText("material rock { material = rock; }\n"
                              "pipeline { start; caves; subtract cave material sand; weather material rock; }");
    ASSERT_TRUE(parsed.diagnostics.empty());
    // `material` is an ordinary name: a block kind and a key.
    EXPECT_EQ(parsed.file.blocks[0].kind, "material");
    EXPECT_EQ(parsed.file.blocks[0].assignments.at(0).key, "material");
    const std::vector<ast::NameStatement>& names = parsed.file.blocks[1].names;
    ASSERT_EQ(names.size(), 4u);
    EXPECT_FALSE(names[1].clause);
    EXPECT_EQ(names[2].mode, "subtract");
    EXPECT_EQ(names[2].name, "cave");
    ASSERT_TRUE(names[2].clause);
    EXPECT_EQ(names[2].clause->word, "material");
    EXPECT_EQ(names[2].clause->operand, "sand");
    EXPECT_EQ(names[2].clause->operandLoc.column, 49u);
    // Three words are a stage and a clause; the checker rejects clauses on grammars.
    EXPECT_FALSE(names[3].mode);
    EXPECT_EQ(names[3].name, "weather");
    ASSERT_TRUE(names[3].clause);
    EXPECT_EQ(names[3].clause->wordLoc.column, 63u);
    EXPECT_FALSE(parseText("pipeline { a b c d e; }").diagnostics.empty());
}

TEST(syntax_Parser, StringsAndWeightedStrings) {
    Parsed parsed = parseText("lsystem net {\n"
                              "  axiom = \"F[0Z]\";\n"
                              "  production Z { \"FZ[RFZ]\" tunnel -1; \"F\\\\Z\"; \"RZ\" 0.5; \"LZ\" room; }\n"
                              "}\n");
    ASSERT_TRUE(parsed.diagnostics.empty());
    const ast::Block& block = parsed.file.blocks.at(0);
    const ast::Value& axiom = block.assignments.at(0).value;
    ASSERT_FALSE(axiom.isList());
    EXPECT_EQ(axiom.scalar->kind, ast::Expr::Kind::String);
    EXPECT_EQ(axiom.scalar->name, "F[0Z]");
    EXPECT_EQ(axiom.loc.column, 11u);
    const std::vector<ast::WeightedString>& strings = block.blocks.at(0).strings;
    ASSERT_EQ(strings.size(), 4u);
    EXPECT_EQ(strings[0].text, "FZ[RFZ]");
    EXPECT_EQ(strings[0].loc.line, 3u);
    EXPECT_EQ(strings[0].loc.column, 18u);
    EXPECT_EQ(strings[0].type, "tunnel");
    ASSERT_TRUE(strings[0].weight);
    EXPECT_EQ(strings[0].weight->kind, ast::Expr::Kind::Negate);
    EXPECT_EQ(strings[1].text, "F\\\\Z"); // no escapes: both backslashes are ABOP symbols
    EXPECT_FALSE(strings[1].type);
    EXPECT_FALSE(strings[1].weight);
    EXPECT_FALSE(strings[2].type);
    ASSERT_TRUE(strings[2].weight);
    EXPECT_EQ(strings[2].weight->number, 0.5);
    EXPECT_EQ(strings[3].type, "room");
}

TEST(syntax_Parser, UnterminatedStringIsLocated) {
    Parsed parsed = parseText("lsystem net {\n  axiom = \"Z;\n}\n");
    ASSERT_FALSE(parsed.diagnostics.empty());
    EXPECT_EQ(parsed.diagnostics[0].code, "E0001");
    EXPECT_EQ(parsed.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(parsed.diagnostics[0].loc.column, 11u);
}

TEST(syntax_Parser, EmptyFileIsValidSyntax) {
    Parsed parsed = parseText("");
    EXPECT_TRUE(parsed.diagnostics.empty());
    EXPECT_TRUE(parsed.file.blocks.empty());
}

} // namespace
} // namespace voxc

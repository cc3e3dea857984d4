#include "voxc/syntax/Parser.h"

#include "AstBuilder.h"
#include "SyntaxErrors.h"
#include "VoxcLexer.h"
#include "VoxcParser.h"

#include <ANTLRInputStream.h>
#include <CommonTokenStream.h>

#include <algorithm>
#include <cstdint>

namespace voxc {

namespace {

// Routes the lexer's "no token matches here" errors into the diagnostics.
class ReportingLexer : public grammar::VoxcLexer {
public:
    ReportingLexer(antlr4::CharStream* input, Diagnostics& diagnostics)
        : grammar::VoxcLexer(input), diagnostics_(diagnostics) {}

    void notifyListeners(const antlr4::LexerNoViableAltException&) override {
        reportUnexpectedCharacter(*this, diagnostics_);
    }

private:
    Diagnostics& diagnostics_;
};

// Unterminated block comments reach the token stream on the hidden channel only.
void reportUnterminatedComments(antlr4::CommonTokenStream& tokens, Diagnostics& diagnostics) {
    for (antlr4::Token* token : tokens.getTokens()) {
        if (token->getType() != grammar::VoxcLexer::UNTERMINATED_COMMENT) continue;
        SourceLoc loc = tokenLoc(*token);
        loc.length = 2;
        diagnostics.error("E0001", loc, "unterminated block comment: '/*' has no matching '*/'");
    }
}

ast::File parseReporting(const SourceFile& source, Diagnostics& diagnostics) {
    antlr4::ANTLRInputStream input(source.text());
    ReportingLexer lexer(&input, diagnostics);
    lexer.removeErrorListeners();
    antlr4::CommonTokenStream tokens(&lexer);
    grammar::VoxcParser parser(&tokens);
    parser.removeErrorListeners();
    parser.setErrorHandler(std::make_shared<SyntaxErrorStrategy>(diagnostics));
    grammar::VoxcParser::FileContext* tree = parser.file();
    tokens.fill();
    reportUnterminatedComments(tokens, diagnostics);
    return buildAst(*tree);
}

// The lexer runs ahead of the parser, so its errors can arrive before an earlier parser error.
void forwardInSourceOrder(std::vector<Diagnostic> found, Diagnostics& diagnostics) {
    auto position = [](const Diagnostic& d) {
        return d.loc.line == 0 ? std::pair(UINT32_MAX, UINT32_MAX) : std::pair(d.loc.line, d.loc.column);
    };
    std::stable_sort(found.begin(), found.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) { return position(a) < position(b); });
    for (Diagnostic& diagnostic : found) diagnostics.report(std::move(diagnostic));
}

} // namespace

ast::File parse(const SourceFile& source, Diagnostics& diagnostics) {
    Diagnostics syntaxErrors;
    ast::File file = parseReporting(source, syntaxErrors);
    forwardInSourceOrder(syntaxErrors.take(), diagnostics);
    return file;
}

} // namespace voxc

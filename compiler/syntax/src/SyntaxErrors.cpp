#include "SyntaxErrors.h"

#include "VoxcLexer.h"

#include <Parser.h>
#include <Token.h>
#include <TokenStream.h>
#include <Vocabulary.h>
#include <misc/IntervalSet.h>

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

namespace voxc {

using antlr4::Token;

SourceLoc tokenLoc(const Token& token) {
    SourceLoc loc;
    loc.line = uint32_t(token.getLine());
    loc.column = uint32_t(token.getCharPositionInLine()) + 1;
    bool hasText = token.getType() != Token::EOF && token.getStopIndex() >= token.getStartIndex();
    loc.length = hasText ? uint32_t(token.getStopIndex() - token.getStartIndex() + 1) : 1;
    return loc;
}

namespace {

constexpr size_t kMaxExpectedListed = 4;

std::string describeExpected(const antlr4::dfa::Vocabulary& vocabulary, size_t type) {
    switch (type) {
    case Token::EOF: return "end of file";
    case grammar::VoxcLexer::IDENT: return "a name";
    case grammar::VoxcLexer::NUMBER: return "a number";
    case grammar::VoxcLexer::STRING: return "a string";
    default: return vocabulary.getDisplayName(type); // literal tokens display as 'x'
    }
}

std::string describeFound(const Token* token) {
    if (token == nullptr || token->getType() == Token::EOF) return "end of file";
    return fmt::format("'{}'", token->getText());
}

bool isOperator(antlr4::Parser* parser, ssize_t type) {
    std::string name = parser->getVocabulary().getDisplayName(size_t(type));
    return name == "'+'" || name == "'-'" || name == "'*'" || name == "'/'" || name == "'&'" || name == "'('";
}

// "';'", "']' or ','", "a name, '{' or ';'"; empty when the set is too large to help.
// Operators that could continue an expression are left out when anything else would do:
// after `[1, 2` the helpful answer is "',' or ']'", not "'+', '-', '*', '/', ',' or ']'".
std::string expectedList(antlr4::Parser* parser, const antlr4::misc::IntervalSet& expected) {
    std::vector<ssize_t> all = expected.toList();
    std::vector<ssize_t> types;
    std::copy_if(all.begin(), all.end(), std::back_inserter(types), [&](ssize_t t) { return !isOperator(parser, t); });
    if (types.empty()) types = all;
    if (types.empty() || types.size() > kMaxExpectedListed) return {};
    std::string out;
    for (size_t i = 0; i < types.size(); ++i) {
        if (i > 0) out += i + 1 == types.size() ? " or " : ", ";
        out += describeExpected(parser->getVocabulary(), size_t(types[i]));
    }
    return out;
}

void reportAt(Diagnostics& diagnostics, const Token* token, std::string message) {
    diagnostics.error("E0001", token ? tokenLoc(*token) : SourceLoc{}, std::move(message));
}

// "expected X, found Y" where the expected set is short, "unexpected Y" otherwise.
std::string mismatch(antlr4::Parser* parser, const antlr4::misc::IntervalSet& expected, const Token* found) {
    std::string list = expectedList(parser, expected);
    if (list.empty()) return fmt::format("unexpected {}", describeFound(found));
    return fmt::format("expected {}, found {}", list, describeFound(found));
}

} // namespace

void SyntaxErrorStrategy::reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) {
    reportAt(diagnostics_, e.getOffendingToken(), mismatch(parser, e.getExpectedTokens(), e.getOffendingToken()));
}

void SyntaxErrorStrategy::reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) {
    reportAt(diagnostics_, e.getOffendingToken(), mismatch(parser, e.getExpectedTokens(), e.getOffendingToken()));
}

void SyntaxErrorStrategy::reportFailedPredicate(antlr4::Parser*, const antlr4::FailedPredicateException& e) {
    reportAt(diagnostics_, e.getOffendingToken(), fmt::format("unexpected {}", describeFound(e.getOffendingToken())));
}

void SyntaxErrorStrategy::reportUnwantedToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    Token* token = parser->getCurrentToken();
    reportAt(diagnostics_, token, mismatch(parser, getExpectedTokens(parser), token));
}

void SyntaxErrorStrategy::reportMissingToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    std::string list = expectedList(parser, getExpectedTokens(parser));
    if (list.empty()) {
        reportAt(diagnostics_, parser->getCurrentToken(),
                 fmt::format("unexpected {}", describeFound(parser->getCurrentToken())));
        return;
    }
    std::string message = fmt::format("expected {}", list);
    // Point just past the previous token, where the missing one belongs (`x = 1` ^ `}`).
    const Token* previous = parser->getTokenStream()->LT(-1);
    if (previous == nullptr) {
        reportAt(diagnostics_, parser->getCurrentToken(), message);
        return;
    }
    SourceLoc loc = tokenLoc(*previous);
    loc.column += loc.length;
    loc.length = 1;
    // A missing ';' is certain: offer it, as clang's fix-it.
    std::vector<FixIt> fixits;
    if (list == "';'") fixits.push_back({{loc.line, loc.column, 0}, ";"});
    diagnostics_.error("E0001", loc, message, {}, std::move(fixits));
}

void reportUnexpectedCharacter(antlr4::Lexer& lexer, Diagnostics& diagnostics) {
    SourceLoc loc;
    loc.line = uint32_t(lexer.tokenStartLine);
    loc.column = uint32_t(lexer.tokenStartCharPositionInLine) + 1;
    antlr4::CharStream* input = lexer.getInputStream();
    size_t start = lexer.tokenStartCharIndex;
    std::string text = input->getText(antlr4::misc::Interval(start, start));
    diagnostics.error("E0001", loc, fmt::format("unexpected character '{}'", text));
}

} // namespace voxc

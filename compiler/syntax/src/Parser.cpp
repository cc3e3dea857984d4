#include "voxc/syntax/Parser.h"

#include "AstBuilder.h"
#include "SyntaxErrors.h"
#include "VoxcLexer.h"
#include "VoxcParser.h"

#include <ANTLRInputStream.h>
#include <CommonTokenStream.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace voxc {

namespace {

// Unterminated strings, like comments, reach the token stream on the hidden channel only.
void reportUnterminatedStrings(antlr4::CommonTokenStream& tokens, Diagnostics& diagnostics) {
    for (antlr4::Token* token : tokens.getTokens()) {
        if (token->getType() != grammar::VoxcLexer::UNTERMINATED_STRING) continue;
        SourceLoc loc = tokenLoc(*token);
        loc.length = 1;
        diagnostics.error("E0001", loc, "unterminated string: '\"' has no closing '\"' on its line");
    }
}

// Thrown to abandon a parse once more errors than Diagnostics shows have been found: the rest
// would be dropped anyway, and a file of garbage would otherwise cost an exception per byte.
struct TooManyErrors {};

bool errorsFull(const Diagnostics& diagnostics) { return diagnostics.errorCount() >= Diagnostics::kMaxErrors; }

// Routes the lexer's "no token matches here" errors into the diagnostics.
class ReportingLexer : public grammar::VoxcLexer {
public:
    ReportingLexer(antlr4::CharStream* input, Diagnostics& diagnostics)
        : grammar::VoxcLexer(input), diagnostics_(diagnostics) {}

    void notifyListeners(const antlr4::LexerNoViableAltException&) override {
        const bool full = errorsFull(diagnostics_);
        reportUnexpectedCharacter(*this, diagnostics_); // past the cap: adds the "too many errors" line
        if (full) throw TooManyErrors{};
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

// Thrown to abandon a parse whose rule invocations nest deeper than the limit. The generated
// rule functions catch only RecognitionException, so it unwinds straight to parseReporting.
struct NestingTooDeep {};

std::string nestingMessage(uint32_t maxNesting) {
    return fmt::format("nesting is deeper than the limit of {} levels (each bracket, call, block, unary operator, "
                       "'let', '?:' branch and operator of a chain adds a level)",
                       maxNesting);
}

// Counts how deeply rule invocations nest while parsing and stops at the limit, before the
// recursive-descent parser (one C++ frame per level) can exhaust the stack.
class DepthLimitedParser : public grammar::VoxcParser {
public:
    DepthLimitedParser(antlr4::TokenStream* tokens, uint32_t maxNesting, Diagnostics& diagnostics)
        : grammar::VoxcParser(tokens), maxNesting_(maxNesting), diagnostics_(diagnostics) {}

    // Recovery keeps reporting to the end of the file; past the cap nothing more is shown.
    antlr4::Token* consume() override {
        if (errorsFull(diagnostics_)) {
            const antlr4::Token* at = getCurrentToken();
            diagnostics_.error("E0001", at ? tokenLoc(*at) : SourceLoc{}, "too many syntax errors");
            throw TooManyErrors{};
        }
        return grammar::VoxcParser::consume();
    }

    using grammar::VoxcParser::enterRecursionRule;
    void enterRule(antlr4::ParserRuleContext* ctx, size_t state, size_t ruleIndex) override {
        checkDepth(ctx);
        grammar::VoxcParser::enterRule(ctx, state, ruleIndex);
    }
    void enterRecursionRule(antlr4::ParserRuleContext* ctx, size_t state, size_t ruleIndex, int precedence) override {
        checkDepth(ctx);
        grammar::VoxcParser::enterRecursionRule(ctx, state, ruleIndex, precedence);
    }

    // A left-associative chain (`x + x + ...`) loops inside one rule: each operator wraps the
    // tree so far in a new context, one level deeper, without a new C++ frame. Stopping here
    // saves building (and measuring) the rest of a huge chain.
    void pushNewRecursionContext(antlr4::ParserRuleContext* ctx, size_t state, size_t ruleIndex) override {
        while (!frames_.empty() && frames_.back().parent != ctx->parent) frames_.pop_back();
        if (!frames_.empty() && frames_.back().depth + ++frames_.back().chain > maxNesting_) {
            const antlr4::Token* start = getContext()->getStart();
            diagnostics_.error("E0012", start ? tokenLoc(*start) : SourceLoc{}, nestingMessage(maxNesting_));
            throw NestingTooDeep{};
        }
        grammar::VoxcParser::pushNewRecursionContext(ctx, state, ruleIndex);
    }

private:
    // A rule's depth is its parent's plus one. ANTLR gives no hook where a rule exits, so the
    // frames of rules that are still open are found from the parent: the frame whose context
    // it is, or whose context it replaced (a labelled alternative or left-recursion wrapper,
    // which keeps the original's parent); frames above that one have exited.
    struct Frame {
        const antlr4::tree::ParseTree* ctx;
        const antlr4::tree::ParseTree* parent;
        uint32_t depth;
        uint32_t chain = 0; // operators of a left-associative chain so far
    };

    uint32_t enter(const antlr4::tree::ParseTree* ctx) {
        const antlr4::tree::ParseTree* parent = ctx->parent;
        while (!frames_.empty() && frames_.back().ctx != parent &&
               !(parent != nullptr && frames_.back().parent == parent->parent))
            frames_.pop_back();
        const uint32_t depth = frames_.empty() ? 1 : frames_.back().depth + 1;
        frames_.push_back({ctx, parent, depth, 0});
        return depth;
    }

    void checkDepth(antlr4::ParserRuleContext* ctx) {
        if (enter(ctx) <= maxNesting_) return;
        const antlr4::Token* at = getCurrentToken();
        diagnostics_.error("E0012", at ? tokenLoc(*at) : SourceLoc{}, nestingMessage(maxNesting_));
        throw NestingTooDeep{};
    }

    uint32_t maxNesting_;
    Diagnostics& diagnostics_;
    std::vector<Frame> frames_;
};

// A left-associative chain (`x + x + ...`) parses in a loop, so the parser's stack stays flat
// while the tree it builds gets one level deeper per operator. Measured without recursion, so
// that the AST builder and every later pass only ever walk trees within the limit. Reports the
// first rule (in source order) that lies too deep.
bool reportIfTreeTooDeep(antlr4::tree::ParseTree* root, uint32_t maxNesting, Diagnostics& diagnostics) {
    std::vector<std::pair<antlr4::tree::ParseTree*, uint32_t>> pending{{root, 1}};
    while (!pending.empty()) {
        auto [node, depth] = pending.back();
        pending.pop_back();
        if (node->children.empty()) continue; // a token
        if (depth > maxNesting) {
            auto* rule = dynamic_cast<antlr4::ParserRuleContext*>(node);
            diagnostics.error("E0012", rule && rule->getStart() ? tokenLoc(*rule->getStart()) : SourceLoc{},
                              nestingMessage(maxNesting));
            return true;
        }
        for (auto child = node->children.rbegin(); child != node->children.rend(); ++child)
            pending.emplace_back(*child, depth + 1);
    }
    return false;
}

ast::File parseReporting(const SourceFile& source, Diagnostics& diagnostics, uint32_t maxNesting) {
    antlr4::ANTLRInputStream input(source.text());
    ReportingLexer lexer(&input, diagnostics);
    lexer.removeErrorListeners();
    antlr4::CommonTokenStream tokens(&lexer);
    DepthLimitedParser parser(&tokens, maxNesting, diagnostics);
    parser.removeErrorListeners();
    parser.setErrorHandler(std::make_shared<SyntaxErrorStrategy>(diagnostics));
    grammar::VoxcParser::FileContext* tree = nullptr;
    try {
        tree = parser.file();
    } catch (const NestingTooDeep&) {
        return {};
    } catch (const TooManyErrors&) {
        return {};
    }
    tokens.fill();
    reportUnterminatedComments(tokens, diagnostics);
    reportUnterminatedStrings(tokens, diagnostics);
    if (reportIfTreeTooDeep(tree, maxNesting, diagnostics)) return {};
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

namespace {

// Where a ';' would end the line before `loc`: just past its last character that is neither blank
// nor in a `//` comment. Nothing when that line ends an item already (`;`, `{`, `}`) or is in
// the middle of one (`,`, `[`, `(`, `=` and the operators), or when there is no such line.
std::optional<SourceLoc> endOfPreviousLine(const SourceFile& source, SourceLoc loc) {
    for (uint32_t line = loc.line; line-- > 1;) {
        std::string_view text = source.line(line);
        bool quoted = false;
        for (size_t i = 0; i + 1 < text.size(); ++i) {
            if (text[i] == '"') quoted = !quoted;
            if (!quoted && text[i] == '/' && text[i + 1] == '/') {
                text = text.substr(0, i);
                break;
            }
        }
        const size_t last = text.find_last_not_of(" \t\r");
        if (last == std::string_view::npos) continue; // blank: look further up
        if (std::string_view(";{}[(,=+-*/&|<>!?:.").find(text[last]) != std::string_view::npos) return std::nullopt;
        // Columns count characters; a line with other than ASCII before the end is left alone.
        for (size_t i = 0; i <= last; ++i)
            if (static_cast<unsigned char>(text[i]) >= 0x80) return std::nullopt;
        return SourceLoc{line, uint32_t(last + 2), 1};
    }
    return std::nullopt;
}

size_t offsetOf(const SourceFile& source, SourceLoc loc) {
    const std::string_view line = source.line(loc.line);
    return size_t(line.data() - source.text().data()) + loc.column - 1;
}

bool before(SourceLoc a, SourceLoc b) { return a.line < b.line || (a.line == b.line && a.column < b.column); }

} // namespace

ast::File parse(const SourceFile& source, Diagnostics& diagnostics, uint32_t maxNesting) {
    Diagnostics syntaxErrors;
    ast::File file = parseReporting(source, syntaxErrors, maxNesting);
    std::vector<Diagnostic> found = syntaxErrors.take();
    // A syntax error at the start of a line after a line that does not end its item is most often
    // a ';' missing there. When the file with that ';' parses past the error, that is the one
    // error to report, as "expected ';'" where it belongs, with the ';' as its fix-it.
    const auto first = std::find_if(found.begin(), found.end(), [](const Diagnostic& d) {
        return d.code == "E0001" && d.loc.line > 0 && !d.file;
    });
    if (first != found.end()) {
        if (const std::optional<SourceLoc> at = endOfPreviousLine(source, first->loc)) {
            std::string fixed = source.text();
            fixed.insert(offsetOf(source, *at), ";");
            Diagnostics retry;
            parseReporting(SourceFile(source.path(), fixed), retry, maxNesting);
            const std::vector<Diagnostic>& rest = retry.all();
            const bool fixes = std::none_of(rest.begin(), rest.end(), [&](const Diagnostic& d) {
                return d.code == "E0001" && !before(first->loc, d.loc);
            });
            if (fixes) {
                const uint32_t line = at->line;
                const std::string_view text = source.line(line);
                const size_t wordStart = text.find_last_of(" \t", at->column - 2);
                const std::string_view word = text.substr(wordStart == std::string_view::npos ? 0 : wordStart + 1,
                                                          at->column - 1 - (wordStart == std::string_view::npos ? 0 : wordStart + 1));
                Diagnostic missing{Severity::Error, "E0001", *at, fmt::format("expected ';' after '{}'", word), {}, nullptr,
                                   {{{line, at->column, 0}, ";"}}};
                // The rest is what the file with the ';' reports, all of it after the ';'.
                std::vector<Diagnostic> kept = retry.take();
                kept.insert(kept.begin(), std::move(missing));
                found = std::move(kept);
            }
        }
    }
    forwardInSourceOrder(std::move(found), diagnostics);
    return file;
}

} // namespace voxc

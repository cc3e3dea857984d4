#include "AstBuilder.h"

#include "SyntaxErrors.h"

#include <algorithm>
#include <charconv>
#include <limits>

namespace voxc {

namespace {

using P = grammar::VoxcParser;

// From the first token of a rule to its last, clipped to one line when rendered.
SourceLoc contextLoc(antlr4::ParserRuleContext& ctx) {
    const antlr4::Token* start = ctx.getStart();
    const antlr4::Token* stop = ctx.getStop();
    if (start == nullptr) return {};
    SourceLoc loc = tokenLoc(*start);
    if (stop != nullptr && stop->getStopIndex() != size_t(-1) && stop->getStopIndex() >= start->getStartIndex())
        loc.length = uint32_t(stop->getStopIndex() - start->getStartIndex() + 1);
    return loc;
}

std::string nodeText(antlr4::tree::TerminalNode* node) { return node ? node->getText() : std::string(); }

// The decimal exponent of the first significant digit: 2 for "123.4", -1 for "0.05", 999 for
// "1e999". Saturates far beyond any double's range. Only called for digit strings.
int64_t leadingExponent(const std::string& text) {
    size_t exponentAt = text.find_first_of("eE");
    std::string_view mantissa = std::string_view(text).substr(0, exponentAt);
    int64_t exponent = 0;
    if (exponentAt != std::string::npos) {
        size_t i = exponentAt + 1;
        bool negative = i < text.size() && text[i] == '-';
        if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
        for (; i < text.size(); ++i) exponent = std::min<int64_t>(exponent * 10 + (text[i] - '0'), int64_t(1) << 40);
        if (negative) exponent = -exponent;
    }
    size_t point = mantissa.find('.');
    size_t integerDigits = point == std::string_view::npos ? mantissa.size() : point;
    size_t first = mantissa.find_first_of("123456789");
    if (first == std::string_view::npos) return 0;
    int64_t position = first < integerDigits ? int64_t(integerDigits - first) - 1 : -int64_t(first - integerDigits);
    return exponent + position;
}

// A literal beyond the double range reads as infinity (which the checker reports as E0007);
// one too small to represent reads as zero.
double parseNumber(const std::string& text) {
    double value = 0.0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range)
        return leadingExponent(text) > 0 ? std::numeric_limits<double>::infinity() : 0.0;
    return value;
}

std::unique_ptr<const ast::Expr> buildExpr(P::ExprContext* ctx);

std::unique_ptr<const ast::Expr> binary(ast::Expr::Kind kind, P::ExprContext* ctx, P::ExprContext* lhs,
                                        P::ExprContext* rhs) {
    auto expr = std::make_unique<ast::Expr>();
    expr->kind = kind;
    expr->loc = contextLoc(*ctx);
    expr->lhs = buildExpr(lhs);
    expr->rhs = buildExpr(rhs);
    return expr;
}

std::unique_ptr<const ast::Expr> buildExpr(P::ExprContext* ctx) {
    if (ctx == nullptr) return std::make_unique<ast::Expr>();
    if (auto* paren = dynamic_cast<P::ParenExprContext*>(ctx)) return buildExpr(paren->expr());
    auto expr = std::make_unique<ast::Expr>();
    expr->loc = contextLoc(*ctx);
    if (auto* number = dynamic_cast<P::NumberExprContext*>(ctx)) {
        expr->kind = ast::Expr::Kind::Number;
        expr->number = parseNumber(nodeText(number->NUMBER()));
    } else if (auto* name = dynamic_cast<P::NameExprContext*>(ctx)) {
        expr->kind = ast::Expr::Kind::Name;
        expr->name = nodeText(name->IDENT());
    } else if (auto* negate = dynamic_cast<P::NegateExprContext*>(ctx)) {
        expr->kind = ast::Expr::Kind::Negate;
        expr->lhs = buildExpr(negate->expr());
    } else if (auto* mul = dynamic_cast<P::MulExprContext*>(ctx)) {
        bool divide = mul->op && mul->op->getText() == "/";
        return binary(divide ? ast::Expr::Kind::Divide : ast::Expr::Kind::Multiply, ctx, mul->expr(0), mul->expr(1));
    } else if (auto* add = dynamic_cast<P::AddExprContext*>(ctx)) {
        bool subtract = add->op && add->op->getText() == "-";
        return binary(subtract ? ast::Expr::Kind::Subtract : ast::Expr::Kind::Add, ctx, add->expr(0), add->expr(1));
    }
    return expr;
}

std::unique_ptr<const ast::Expr> buildFieldExpr(P::FieldExprContext* ctx);

ast::Expr::Kind binaryKind(const std::string& op) {
    using K = ast::Expr::Kind;
    static const std::pair<const char*, K> kinds[] = {
        {"+", K::Add},   {"-", K::Subtract},     {"*", K::Multiply}, {"/", K::Divide},
        {"<", K::Less},  {"<=", K::LessEqual},   {">", K::Greater},  {">=", K::GreaterEqual},
        {"==", K::Equal}, {"!=", K::NotEqual},   {"&&", K::And},     {"||", K::Or}};
    for (const auto& [text, kind] : kinds)
        if (op == text) return kind;
    return K::Add; // unreachable for a tree the parser accepted; error recovery may leave no operator
}

std::unique_ptr<const ast::Expr> buildFieldExpr(P::FieldExprContext* ctx) {
    if (ctx == nullptr) return std::make_unique<ast::Expr>();
    if (auto* paren = dynamic_cast<P::FieldParenContext*>(ctx)) return buildFieldExpr(paren->fieldExpr());
    auto expr = std::make_unique<ast::Expr>();
    expr->loc = contextLoc(*ctx);
    using K = ast::Expr::Kind;
    if (auto* number = dynamic_cast<P::FieldNumberContext*>(ctx)) {
        expr->kind = K::Number;
        expr->number = parseNumber(nodeText(number->NUMBER()));
    } else if (auto* name = dynamic_cast<P::FieldNameContext*>(ctx)) {
        expr->kind = K::Name;
        expr->name = nodeText(name->IDENT());
    } else if (auto* unary = dynamic_cast<P::FieldUnaryContext*>(ctx)) {
        expr->kind = unary->op && unary->op->getText() == "!" ? K::Not : K::Negate;
        expr->lhs = buildFieldExpr(unary->fieldExpr());
    } else if (auto* binary = dynamic_cast<P::FieldBinaryContext*>(ctx)) {
        expr->kind = binaryKind(binary->op ? binary->op->getText() : std::string());
        expr->lhs = buildFieldExpr(binary->fieldExpr(0));
        expr->rhs = buildFieldExpr(binary->fieldExpr(1));
    } else if (auto* call = dynamic_cast<P::FieldCallContext*>(ctx)) {
        expr->kind = K::Call;
        if (call->callee) {
            expr->name = call->callee->getText();
            expr->nameLoc = tokenLoc(*call->callee);
        }
        for (P::FieldExprContext* arg : call->fieldExpr()) expr->operands.push_back(buildFieldExpr(arg));
    } else if (auto* member = dynamic_cast<P::FieldMemberContext*>(ctx)) {
        expr->kind = K::Member;
        expr->lhs = buildFieldExpr(member->fieldExpr());
        if (member->swizzle) {
            expr->name = member->swizzle->getText();
            expr->nameLoc = tokenLoc(*member->swizzle);
        }
    } else if (auto* conditional = dynamic_cast<P::FieldConditionalContext*>(ctx)) {
        expr->kind = K::Conditional;
        for (size_t i = 0; i < 3; ++i) expr->operands.push_back(buildFieldExpr(conditional->fieldExpr(i)));
    } else if (auto* let = dynamic_cast<P::FieldLetContext*>(ctx)) {
        expr->kind = K::Let;
        if (let->name) {
            expr->name = let->name->getText();
            expr->nameLoc = tokenLoc(*let->name);
        }
        expr->lhs = buildFieldExpr(let->fieldExpr(0));
        expr->rhs = buildFieldExpr(let->fieldExpr(1));
    }
    return expr;
}

// The STRING token's text without its quotes (the lexer guarantees both).
std::string unquoted(const std::string& token) {
    return token.size() >= 2 ? token.substr(1, token.size() - 2) : std::string();
}

ast::Value buildValue(P::ValueContext* ctx) {
    ast::Value value;
    if (ctx == nullptr) {
        value.scalar = std::make_unique<ast::Expr>();
        return value;
    }
    value.loc = contextLoc(*ctx);
    if (auto* scalar = dynamic_cast<P::ScalarValueContext*>(ctx)) {
        value.scalar = buildExpr(scalar->expr());
    } else if (auto* string = dynamic_cast<P::StringValueContext*>(ctx)) {
        auto expr = std::make_unique<ast::Expr>();
        expr->kind = ast::Expr::Kind::String;
        expr->loc = value.loc;
        expr->name = unquoted(nodeText(string->STRING()));
        value.scalar = std::move(expr);
    } else if (auto* list = dynamic_cast<P::ListValueContext*>(ctx)) {
        for (P::ValueContext* element : list->value()) value.elements.push_back(buildValue(element));
    } else {
        value.scalar = std::make_unique<ast::Expr>();
    }
    return value;
}

ast::Row buildRow(P::RowContext& ctx) {
    ast::Row row;
    row.loc = contextLoc(ctx);
    for (P::CellContext* cellCtx : ctx.cell()) {
        ast::Cell cell;
        cell.loc = contextLoc(*cellCtx);
        for (P::TermContext* termCtx : cellCtx->term()) {
            ast::Term term;
            term.loc = contextLoc(*termCtx);
            term.op = termCtx->op ? termCtx->op->getText() : std::string();
            term.opLoc = termCtx->op ? tokenLoc(*termCtx->op) : term.loc;
            if (termCtx->expr()) term.value = buildExpr(termCtx->expr());
            cell.terms.push_back(std::move(term));
        }
        row.cells.push_back(std::move(cell));
    }
    return row;
}

ast::Block buildBlock(P::BlockContext& ctx) {
    ast::Block block;
    if (ctx.kind) {
        block.loc = tokenLoc(*ctx.kind);
        block.kind = ctx.kind->getText();
    }
    if (ctx.getStop() && ctx.getStop()->getText() == "}") block.end = tokenLoc(*ctx.getStop());
    if (ctx.label) {
        block.label = ctx.label->getText();
        block.labelLoc = tokenLoc(*ctx.label);
    }
    for (P::MemberContext* member : ctx.member()) {
        if (auto* assignment = member->assignment()) {
            ast::Assignment a;
            a.loc = assignment->key ? tokenLoc(*assignment->key) : contextLoc(*assignment);
            a.key = assignment->key ? assignment->key->getText() : std::string();
            a.value = buildValue(assignment->value());
            block.assignments.push_back(std::move(a));
        } else if (auto* nested = member->block()) {
            block.blocks.push_back(buildBlock(*nested));
        } else if (auto* row = member->row()) {
            block.rows.push_back(buildRow(*row));
        } else if (auto* name = member->nameStatement()) {
            ast::NameStatement statement;
            if (name->name) {
                statement.loc = tokenLoc(*name->name);
                statement.name = name->name->getText();
            }
            if (name->combine) {
                statement.mode = name->combine->getText();
                statement.modeLoc = tokenLoc(*name->combine);
            }
            if (name->clause && name->operand)
                statement.clause = ast::StageClause{name->clause->getText(), tokenLoc(*name->clause),
                                                    name->operand->getText(), tokenLoc(*name->operand)};
            block.names.push_back(std::move(statement));
        } else if (auto* weighted = member->weightedString()) {
            ast::WeightedString entry;
            if (weighted->text) {
                entry.loc = tokenLoc(*weighted->text);
                entry.text = unquoted(weighted->text->getText());
            }
            if (weighted->type) {
                entry.type = weighted->type->getText();
                entry.typeLoc = tokenLoc(*weighted->type);
            }
            if (weighted->weight) entry.weight = buildExpr(weighted->weight);
            block.strings.push_back(std::move(entry));
        }
    }
    return block;
}

} // namespace

ast::File buildAst(P::FileContext& file) {
    ast::File out;
    for (P::ItemContext* item : file.item()) {
        if (auto* constant = item->constDecl()) {
            ast::ConstDecl decl;
            decl.loc = constant->name ? tokenLoc(*constant->name) : contextLoc(*constant);
            decl.name = constant->name ? constant->name->getText() : std::string();
            decl.value = buildExpr(constant->expr());
            out.constants.push_back(std::move(decl));
        } else if (auto* function = item->functionDecl()) {
            ast::FunctionDecl decl;
            decl.loc = function->name ? tokenLoc(*function->name) : contextLoc(*function);
            decl.name = function->name ? function->name->getText() : std::string();
            for (P::ParameterContext* parameter : function->parameter()) {
                ast::Parameter p;
                p.loc = parameter->name ? tokenLoc(*parameter->name) : contextLoc(*parameter);
                p.name = parameter->name ? parameter->name->getText() : std::string();
                p.type = parameter->type ? parameter->type->getText() : std::string();
                p.typeLoc = parameter->type ? tokenLoc(*parameter->type) : p.loc;
                decl.parameters.push_back(std::move(p));
            }
            decl.result = function->result ? function->result->getText() : std::string();
            decl.resultLoc = function->result ? tokenLoc(*function->result) : decl.loc;
            decl.body = buildFieldExpr(function->fieldExpr());
            out.functions.push_back(std::move(decl));
        } else if (auto* field = item->fieldDecl()) {
            ast::FieldDecl decl;
            decl.loc = field->name ? tokenLoc(*field->name) : contextLoc(*field);
            decl.name = field->name ? field->name->getText() : std::string();
            decl.value = buildFieldExpr(field->fieldExpr());
            out.fields.push_back(std::move(decl));
        } else if (auto* feature = item->featureDecl()) {
            ast::FeatureDecl decl;
            decl.loc = feature->name ? tokenLoc(*feature->name) : contextLoc(*feature);
            decl.name = feature->name ? feature->name->getText() : std::string();
            if (feature->block()) decl.body = buildBlock(*feature->block());
            out.features.push_back(std::move(decl));
        } else if (auto* block = item->block()) {
            out.blocks.push_back(buildBlock(*block));
        }
    }
    return out;
}

} // namespace voxc

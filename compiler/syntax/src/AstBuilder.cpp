#include "AstBuilder.h"

#include "SyntaxErrors.h"

#include <charconv>

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

SourceLoc nodeLoc(antlr4::tree::TerminalNode* node) {
    return node && node->getSymbol() ? tokenLoc(*node->getSymbol()) : SourceLoc{};
}

std::string nodeText(antlr4::tree::TerminalNode* node) { return node ? node->getText() : std::string(); }

double parseNumber(const std::string& text) {
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
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

ast::Value buildValue(P::ValueContext* ctx) {
    ast::Value value;
    if (ctx == nullptr) {
        value.scalar = std::make_unique<ast::Expr>();
        return value;
    }
    value.loc = contextLoc(*ctx);
    if (auto* scalar = dynamic_cast<P::ScalarValueContext*>(ctx)) {
        value.scalar = buildExpr(scalar->expr());
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
            block.names.push_back({nodeLoc(name->IDENT()), nodeText(name->IDENT())});
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
        } else if (auto* block = item->block()) {
            out.blocks.push_back(buildBlock(*block));
        }
    }
    return out;
}

} // namespace voxc

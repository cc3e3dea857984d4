#pragma once
// The syntax tree of a .vox file, built once by the parser and never changed afterwards:
// the checker reads it and writes its findings into its own tables. Every node has a location.
//
// The tree mirrors the generic surface syntax: a file is constants and blocks; a block holds
// assignments, nested blocks, rows and bare names. What each block may contain is decided
// by the checker, not the parser.
#include "voxc/core/SourceLoc.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace voxc::ast {

// Constant expressions use the first seven kinds; field expressions (fields and function
// bodies) use them all.
struct Expr {
    enum class Kind : uint8_t {
        Number, Name, Negate, Add, Subtract, Multiply, Divide,
        Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual, And, Or, Not,
        Call,        // name(operands...)
        Member,      // lhs.name: a swizzle such as `.x` or `.xz`
        Conditional, // operands[0] ? operands[1] : operands[2]
        Let,         // let name = lhs in rhs
        String       // "text" as a key's value (name holds the text, quotes removed)
    };
    Kind kind = Kind::Number;
    SourceLoc loc;                // the whole expression
    double number = 0.0;          // Number
    std::string name;             // Name, Call (callee), Member (swizzle), Let (bound name), String (the text)
    SourceLoc nameLoc;            // Call, Member, Let: the name alone
    std::unique_ptr<const Expr> lhs; // Negate, Not: the operand; binary kinds: left operand; Member: the vector; Let: the value
    std::unique_ptr<const Expr> rhs; // binary kinds: right operand; Let: the body
    std::vector<std::unique_ptr<const Expr>> operands; // Call arguments; Conditional's three parts
};

// The right-hand side of `key = value;`: a scalar expression or a bracketed list.
struct Value {
    SourceLoc loc;
    std::unique_ptr<const Expr> scalar; // null for a list
    std::vector<Value> elements;        // a list's elements
    bool isList() const { return scalar == nullptr; }
};

struct Assignment {
    SourceLoc loc; // the key
    std::string key;
    Value value;
};

// One operator of a row cell: `GEQ 0.5`, `IGN`, `ADD -HALF`.
struct Term {
    SourceLoc loc;   // operator and value
    std::string op;
    SourceLoc opLoc; // the operator name alone
    std::unique_ptr<const Expr> value; // null when none is written
};

// A cell is one or more terms joined by `&`.
struct Cell {
    SourceLoc loc;
    std::vector<Term> terms;
};

struct Row {
    SourceLoc loc;
    std::vector<Cell> cells;
};

// `material sand` after a pipeline stage's name: a clause word and the name it takes.
struct StageClause {
    std::string word;
    SourceLoc wordLoc;
    std::string operand;
    SourceLoc operandLoc;
};

// A bare `name;` statement, as in `pipeline { start; caves; }`, optionally preceded by a
// mode word and followed by a clause: `subtract cave material sand;`.
struct NameStatement {
    SourceLoc loc;
    std::string name;
    std::optional<std::string> mode;
    SourceLoc modeLoc;
    std::optional<StageClause> clause;
};

// `"FLFLFZ" tunnel 1;` in an L-system production or macro block; type and weight are optional.
struct WeightedString {
    SourceLoc loc;     // the quoted text, quotes included
    std::string text;  // without the quotes; its first character is at loc.column + 1
    std::optional<std::string> type;
    SourceLoc typeLoc;
    std::unique_ptr<const Expr> weight; // null when none is written
};

// `kind label { ... }`. Members of each sort keep their written order.
struct Block {
    SourceLoc loc; // the kind word
    SourceLoc end; // the closing brace (line 0 when the parser recovered without one)
    std::string kind;
    std::optional<std::string> label;
    SourceLoc labelLoc;
    std::vector<Assignment> assignments;
    std::vector<Block> blocks;
    std::vector<Row> rows;
    std::vector<NameStatement> names;
    std::vector<WeightedString> strings;
};

struct ConstDecl {
    SourceLoc loc; // the name
    std::string name;
    std::unique_ptr<const Expr> value;
};

struct Parameter {
    SourceLoc loc; // the name
    std::string name;
    std::string type;
    SourceLoc typeLoc;
};

// `fn name(params) -> result = body;`
struct FunctionDecl {
    SourceLoc loc; // the name
    std::string name;
    std::vector<Parameter> parameters;
    std::string result;
    SourceLoc resultLoc;
    std::unique_ptr<const Expr> body;
};

// `field name = value;`
struct FieldDecl {
    SourceLoc loc; // the name
    std::string name;
    std::unique_ptr<const Expr> value;
};

// `feature name = generator { key = value; ... }`: `body.kind` names the generator.
struct FeatureDecl {
    SourceLoc loc; // the name
    std::string name;
    Block body;
};

struct File {
    std::vector<ConstDecl> constants;    // declaration order
    std::vector<FunctionDecl> functions; // declaration order
    std::vector<FieldDecl> fields;       // declaration order
    std::vector<FeatureDecl> features;   // declaration order
    std::vector<Block> blocks;           // declaration order
};

} // namespace voxc::ast

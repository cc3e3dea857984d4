#pragma once
// Lowers field expressions (ast::Expr) into a FieldDag: names resolve to let bindings,
// parameters, position inputs or constants; operators and calls become builtin calls typed by
// the registry's type rules; user functions are inlined at each call, by sharing: a function
// lowered once for a list of argument nodes reuses that result at every call with the same list,
// so a chain of functions that each call the previous one twice costs linear work, not 2^n.
// Lowering stops after Limits::maxLoweringSteps expression nodes (exhausted(); the caller
// reports it) and where expressions, counted through inlined calls, nest deeper than
// Limits::maxFieldDepth (E0012 there), which also bounds this recursion's stack.
//
// Numbers (literals, constants, and + - * / and unary minus of numbers) are folded in double
// precision like `const` expressions and stay untyped until used: an argument position whose
// type rule wants an int takes an integral number as an int, anywhere else it is a float.
#include "Context.h"

#include "voxc/program/FieldDag.h"
#include "voxc/syntax/Ast.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace voxc {
struct FunctionInfo;
}

namespace voxc::check {

// A lowered expression: a node, or a number not yet given a type. `ok` is false after an
// error, which has then been reported; users of a failed value report nothing more.
struct Lowered {
    bool ok = true;
    std::optional<double> number;
    uint32_t node = 0;
    Type type = Type::Float;

    static Lowered failed() { return {false, std::nullopt, 0, Type::Float}; }
    static Lowered ofNumber(double value) { return {true, value, 0, Type::Float}; }
    static Lowered ofNode(uint32_t node, Type type) { return {true, std::nullopt, node, type}; }
};

using FunctionTable = std::map<std::string, const ast::FunctionDecl*, std::less<>>;

std::optional<Type> parseTypeName(std::string_view name);

class FieldLowering {
public:
    FieldLowering(Context& context, const FunctionTable& functions, FieldDag& dag)
        : context_(context), functions_(functions), dag_(dag) {}

    // A field's value: inputs are visible.
    Lowered lowerField(const ast::Expr& expr);
    // A function's body with its parameters bound to `arguments` (already of the parameter types).
    Lowered lowerFunctionBody(const ast::FunctionDecl& function, const std::vector<Lowered>& arguments);
    // The number as a node of `type` (Float, or Int when it is integral); reports E0007/E0010 at `loc`.
    Lowered materialize(const Lowered& value, Type type, SourceLoc loc);

    // Expression nodes visited so far (a shared function call counts once per argument list).
    uint64_t steps() const { return steps_; }
    // True once lowering stopped at Limits::maxLoweringSteps; nothing about it is reported yet.
    bool exhausted() const { return steps_ > uint64_t(context_.limits.maxLoweringSteps); }

private:
    struct Scope {
        std::vector<std::pair<std::string, Lowered>> bindings; // innermost last
        bool inputs = false;                                   // fields see x, y, z, ...; functions do not
    };

    Lowered lower(const ast::Expr& expr, Scope& scope);
    Lowered lowerNested(const ast::Expr& expr, Scope& scope); // lower() within the depth limit
    Lowered lowerName(const ast::Expr& expr, Scope& scope);
    Lowered lowerArithmetic(const ast::Expr& expr, Scope& scope);
    Lowered lowerMember(const ast::Expr& expr, Scope& scope);
    Lowered lowerCall(const ast::Expr& expr, Scope& scope);
    Lowered callUser(const ast::FunctionDecl& function, const ast::Expr& at, std::vector<Lowered> args);
    // NAME(wx, wz) of a terrain block's map (null: the block had errors).
    Lowered sampleMap(const std::shared_ptr<const SampledMap>& map, const ast::Expr& at, std::vector<Lowered> args);
    Lowered sampleVolume(const std::shared_ptr<const SampledMap>& map, const ast::Expr& at, std::vector<Lowered> args);
    // A call of builtin `name` on `args`; `surface` is how the user wrote it, for messages.
    // `argLocs`: where each argument is written (empty for calls the checker builds itself, such
    // as a swizzle's vec3), so a wrong argument is reported where it is.
    Lowered callBuiltin(std::string_view name, std::vector<Lowered> args, SourceLoc loc, std::string_view surface,
                        std::vector<SourceLoc> argLocs = {});
    // E0010 for a builtin call no typing of its literals fits: at the argument to blame, naming it
    // and the types it needs, when one argument alone is wrong; else at the call, listing them all.
    void reportArgumentTypes(const FunctionInfo& info, const std::vector<Lowered>& args, SourceLoc loc,
                             std::string_view surface, const std::vector<SourceLoc>& argLocs);
    Lowered input(FieldInput which, SourceLoc loc);

    Context& context_;
    const FunctionTable& functions_;
    FieldDag& dag_;
    std::vector<std::string> callStack_; // user functions being inlined, outermost first
    std::map<std::pair<const ast::FunctionDecl*, std::vector<uint32_t>>, Lowered> inlined_;
    uint64_t steps_ = 0;
    uint32_t depth_ = 0;   // lower() calls in progress
    bool tooDeep_ = false; // the depth limit was reported
};

} // namespace voxc::check

#include "FieldLowering.h"

#include "Suggest.h"
#include "Values.h"

#include "voxc/builtins/Functions.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <utility>

namespace voxc::check {

namespace {

using Kind = ast::Expr::Kind;

// Position inputs by name; `p` and `wp` are vectors of the three.
struct InputName {
    std::string_view name;
    FieldInput first;
    bool vector;
};
constexpr InputName kInputs[] = {
    {"x", FieldInput::LocalX, false}, {"y", FieldInput::LocalY, false}, {"z", FieldInput::LocalZ, false},
    {"wx", FieldInput::WorldX, false}, {"wy", FieldInput::WorldY, false}, {"wz", FieldInput::WorldZ, false},
    {"p", FieldInput::LocalX, true},  {"wp", FieldInput::WorldX, true}};

// The registry record of each operator as written.
std::string_view operatorFunction(Kind kind) {
    switch (kind) {
    case Kind::Add: return "add";
    case Kind::Subtract: return "sub";
    case Kind::Multiply: return "mul";
    case Kind::Divide: return "div";
    case Kind::Negate: return "neg";
    case Kind::Less: return "lt";
    case Kind::LessEqual: return "le";
    case Kind::Greater: return "gt";
    case Kind::GreaterEqual: return "ge";
    case Kind::Equal: return "eq";
    case Kind::NotEqual: return "ne";
    case Kind::And: return "and";
    case Kind::Or: return "or";
    case Kind::Not: return "not";
    default: return "";
    }
}

std::string_view operatorText(Kind kind) {
    switch (kind) {
    case Kind::Add: return "+";
    case Kind::Subtract: case Kind::Negate: return "-";
    case Kind::Multiply: return "*";
    case Kind::Divide: return "/";
    case Kind::Less: return "<";
    case Kind::LessEqual: return "<=";
    case Kind::Greater: return ">";
    case Kind::GreaterEqual: return ">=";
    case Kind::Equal: return "==";
    case Kind::NotEqual: return "!=";
    case Kind::And: return "&&";
    case Kind::Or: return "||";
    case Kind::Not: return "!";
    default: return "?";
    }
}

bool fitsInt(double v) { return v == std::floor(v) && v >= -2147483648.0 && v <= 2147483647.0; }

// The arguments' types as written: a number literal shows as int when it is a whole number.
std::string typeList(const std::vector<Lowered>& args) {
    std::string text;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string_view type = args[i].number ? (fitsInt(*args[i].number) ? "int" : "float") : typeName(args[i].type);
        text += fmt::format("{}{}", i ? ", " : "", type);
    }
    return text;
}

constexpr Type kAllTypes[] = {Type::Float, Type::Int, Type::Bool, Type::Vec2, Type::Vec3};

// The result type when every argument keeps its type but `fixed` (an index) takes `fixedType`;
// number literals may be float or int (int only when whole), the first assignment that fits wins
// (its argument types into `chosen` when given).
std::optional<Type> typeWith(const FunctionInfo& info, const std::vector<Lowered>& args, size_t fixed,
                             std::optional<Type> fixedType, std::vector<Type>* chosen = nullptr) {
    std::vector<size_t> numbers;
    for (size_t i = 0; i < args.size(); ++i)
        if (args[i].number && !(i == fixed && fixedType)) numbers.push_back(i);
    if (numbers.size() >= 8) return std::nullopt; // 256 assignments at most; never so many literals in one call
    std::vector<Type> types(args.size());
    for (uint32_t mask = 0; mask < (1u << numbers.size()); ++mask) {
        bool possible = true;
        for (size_t i = 0; i < args.size(); ++i) types[i] = i == fixed && fixedType ? *fixedType : args[i].type;
        for (size_t n = 0; n < numbers.size(); ++n) {
            const bool asInt = (mask >> n) & 1u;
            types[numbers[n]] = asInt ? Type::Int : Type::Float;
            if (asInt && !fitsInt(*args[numbers[n]].number)) possible = false;
        }
        if (!possible) continue;
        if (std::optional<Type> result = info.typeRule(types)) {
            if (chosen) *chosen = types;
            return result;
        }
    }
    return std::nullopt;
}

// The parameter names of the signature's first form: "fbm(p: vec3, octaves: int) -> float" gives
// p, octaves; none for a signature of another shape.
std::vector<std::string_view> parameterNames(std::string_view signature) {
    const size_t open = signature.find('(');
    const size_t close = signature.find(')');
    std::vector<std::string_view> names;
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) return names;
    std::string_view list = signature.substr(open + 1, close - open - 1);
    while (!list.empty()) {
        const size_t comma = list.find(',');
        std::string_view parameter = list.substr(0, comma);
        while (!parameter.empty() && parameter.front() == ' ') parameter.remove_prefix(1);
        names.push_back(parameter.substr(0, parameter.find(':')));
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
    return names;
}

} // namespace

std::optional<Type> parseTypeName(std::string_view name) {
    for (Type t : {Type::Float, Type::Int, Type::Bool, Type::Vec2, Type::Vec3})
        if (typeName(t) == name) return t;
    return std::nullopt;
}

Lowered FieldLowering::lowerField(const ast::Expr& expr) {
    Scope scope;
    scope.inputs = true;
    return lower(expr, scope);
}

Lowered FieldLowering::lowerFunctionBody(const ast::FunctionDecl& function, const std::vector<Lowered>& arguments) {
    Scope scope;
    for (size_t i = 0; i < function.parameters.size() && i < arguments.size(); ++i)
        scope.bindings.emplace_back(function.parameters[i].name, arguments[i]);
    callStack_.push_back(function.name);
    Lowered body = lower(*function.body, scope);
    callStack_.pop_back();
    if (!body.ok) return Lowered::failed();
    const std::optional<Type> result = parseTypeName(function.result);
    if (!result) return Lowered::failed(); // reported with the declaration
    if (body.number) return materialize(body, *result, function.body->loc);
    if (body.type != *result) {
        context_.diagnostics.error("E0010", function.body->loc,
                                   fmt::format("function '{}' is declared to return {} but its body is {}",
                                               function.name, typeName(*result), typeName(body.type)),
                                   {{function.resultLoc, "the result type is declared here"}});
        return Lowered::failed();
    }
    return body;
}

Lowered FieldLowering::materialize(const Lowered& value, Type type, SourceLoc loc) {
    if (!value.ok || !value.number) return value;
    const double v = *value.number;
    FieldNode node;
    node.kind = FieldNode::Kind::Constant;
    node.loc = loc;
    if (type == Type::Int) {
        if (!fitsInt(v)) {
            context_.diagnostics.error("E0010", loc, fmt::format("expected an int, found the number {}", v));
            return Lowered::failed();
        }
        node.type = Type::Int;
        node.constantInt = int32_t(v);
    } else if (type == Type::Float) {
        if (std::fabs(v) > double(std::numeric_limits<float>::max())) {
            context_.diagnostics.error("E0007", loc, "value is too large for a 32-bit float");
            return Lowered::failed();
        }
        node.constant.x = float(v);
    } else {
        context_.diagnostics.error("E0010", loc, fmt::format("expected {}, found a number", typeName(type)));
        return Lowered::failed();
    }
    return Lowered::ofNode(dag_.add(node), node.type);
}

Lowered FieldLowering::input(FieldInput which, SourceLoc loc) {
    FieldNode node;
    node.kind = FieldNode::Kind::Input;
    node.input = which;
    node.loc = loc;
    return Lowered::ofNode(dag_.add(node), Type::Float);
}

Lowered FieldLowering::lower(const ast::Expr& expr, Scope& scope) {
    if (++steps_ > uint64_t(context_.limits.maxLoweringSteps)) return Lowered::failed();
    if (depth_ >= uint32_t(context_.limits.maxFieldDepth)) {
        if (std::exchange(tooDeep_, true)) return Lowered::failed(); // one report per field or function
        context_.diagnostics.error(
            "E0012", expr.loc,
            fmt::format("this expression nests deeper than the limit of {} levels once function calls are inlined{}",
                        context_.limits.maxFieldDepth,
                        callStack_.empty() ? "" : fmt::format(" (through {})", fmt::join(callStack_, " -> "))));
        return Lowered::failed();
    }
    ++depth_;
    Lowered result = lowerNested(expr, scope);
    --depth_;
    return result;
}

Lowered FieldLowering::lowerNested(const ast::Expr& expr, Scope& scope) {
    switch (expr.kind) {
    case Kind::Number:
        if (!std::isfinite(expr.number)) {
            context_.diagnostics.error("E0007", expr.loc, "value is too large to represent");
            return Lowered::failed();
        }
        return Lowered::ofNumber(expr.number);
    case Kind::Name: return lowerName(expr, scope);
    case Kind::Add: case Kind::Subtract: case Kind::Multiply: case Kind::Divide: case Kind::Negate:
        return lowerArithmetic(expr, scope);
    case Kind::Not: return callBuiltin("not", {lower(*expr.lhs, scope)}, expr.loc, "!", {expr.lhs->loc});
    case Kind::Member: return lowerMember(expr, scope);
    case Kind::Call: return lowerCall(expr, scope);
    case Kind::Conditional: {
        std::vector<Lowered> parts;
        std::vector<SourceLoc> locs;
        for (const auto& operand : expr.operands) {
            parts.push_back(lower(*operand, scope));
            locs.push_back(operand->loc);
        }
        return callBuiltin("select", std::move(parts), expr.loc, "?:", std::move(locs));
    }
    case Kind::Let: {
        Lowered value = lower(*expr.lhs, scope);
        scope.bindings.emplace_back(expr.name, value);
        Lowered body = lower(*expr.rhs, scope);
        scope.bindings.pop_back();
        return body;
    }
    default: // comparisons and logic
        return callBuiltin(operatorFunction(expr.kind), {lower(*expr.lhs, scope), lower(*expr.rhs, scope)}, expr.loc,
                           operatorText(expr.kind), {expr.lhs->loc, expr.rhs->loc});
    }
}

Lowered FieldLowering::lowerName(const ast::Expr& expr, Scope& scope) {
    for (auto it = scope.bindings.rbegin(); it != scope.bindings.rend(); ++it)
        if (it->first == expr.name) return it->second;
    if (scope.inputs)
        for (const InputName& in : kInputs) {
            if (in.name != expr.name) continue;
            if (!in.vector) return input(in.first, expr.loc);
            std::vector<Lowered> parts;
            for (int axis = 0; axis < 3; ++axis) parts.push_back(input(FieldInput(int(in.first) + axis), expr.loc));
            return callBuiltin("vec3", std::move(parts), expr.loc, "vec3");
        }
    if (context_.constants.isDeclared(expr.name)) {
        std::optional<double> value = context_.constants.evaluate(expr);
        return value ? Lowered::ofNumber(*value) : Lowered::failed();
    }
    std::vector<std::string_view> known;
    for (const auto& binding : scope.bindings) known.push_back(binding.first);
    if (scope.inputs)
        for (const InputName& in : kInputs) known.push_back(in.name);
    const bool isInput = std::any_of(std::begin(kInputs), std::end(kInputs),
                                     [&](const InputName& in) { return in.name == expr.name; });
    context_.diagnostics.error(
        "E0002", expr.loc,
        isInput ? fmt::format("'{}' is a position input, which function bodies cannot see; pass it as an argument",
                              expr.name)
                : fmt::format("unknown name '{}'{}", expr.name, didYouMean(expr.name, known)));
    return Lowered::failed();
}

// Numbers fold like constants; anything else becomes a call of the operator's record.
Lowered FieldLowering::lowerArithmetic(const ast::Expr& expr, Scope& scope) {
    const bool unary = expr.kind == Kind::Negate;
    Lowered lhs = lower(*expr.lhs, scope);
    Lowered rhs = unary ? Lowered::ofNumber(0.0) : lower(*expr.rhs, scope);
    if (!lhs.ok || !rhs.ok) return Lowered::failed();
    if (lhs.number && rhs.number) {
        const double a = *lhs.number, b = *rhs.number;
        double r = 0.0;
        switch (expr.kind) {
        case Kind::Negate: r = -a; break;
        case Kind::Add: r = a + b; break;
        case Kind::Subtract: r = a - b; break;
        case Kind::Multiply: r = a * b; break;
        default:
            if (b == 0.0) {
                context_.diagnostics.error("E0007", expr.rhs->loc, "division by zero");
                return Lowered::failed();
            }
            r = a / b;
        }
        if (!std::isfinite(r)) {
            context_.diagnostics.error("E0007", expr.loc, "value is too large to represent");
            return Lowered::failed();
        }
        return Lowered::ofNumber(r);
    }
    std::vector<Lowered> args{lhs};
    std::vector<SourceLoc> locs{expr.lhs->loc};
    if (!unary) {
        args.push_back(rhs);
        locs.push_back(expr.rhs->loc);
    }
    return callBuiltin(operatorFunction(expr.kind), std::move(args), expr.loc, operatorText(expr.kind), std::move(locs));
}

// `.x` is a Component node; `.xz`, `.zyx`, ... build a vec2/vec3 of components.
Lowered FieldLowering::lowerMember(const ast::Expr& expr, Scope& scope) {
    Lowered vector = lower(*expr.lhs, scope);
    if (!vector.ok) return Lowered::failed();
    const int width = vector.number ? 0 : vector.type == Type::Vec3 ? 3 : vector.type == Type::Vec2 ? 2 : 0;
    if (width == 0) {
        context_.diagnostics.error("E0010", expr.nameLoc,
                                   fmt::format("'.{}' needs a vec2 or vec3, but this is {}", expr.name,
                                               vector.number ? "a number" : typeName(vector.type)));
        return Lowered::failed();
    }
    const std::string_view letters = width == 3 ? "xyz" : "xy";
    if (expr.name.empty() || expr.name.size() > 3 ||
        expr.name.find_first_not_of(letters) != std::string::npos) {
        context_.diagnostics.error("E0010", expr.nameLoc,
                                   fmt::format("'.{}' is not a swizzle of a {}: use up to three of {}", expr.name,
                                               typeName(vector.type), fmt::join(letters, ", ")));
        return Lowered::failed();
    }
    std::vector<Lowered> components;
    for (char letter : expr.name) {
        FieldNode node;
        node.kind = FieldNode::Kind::Component;
        node.loc = expr.loc;
        node.component = uint32_t(letter - 'x');
        node.operands = {vector.node};
        components.push_back(Lowered::ofNode(dag_.add(node), Type::Float));
    }
    if (components.size() == 1) return components[0];
    const std::string_view constructor = components.size() == 2 ? "vec2" : "vec3";
    return callBuiltin(constructor, std::move(components), expr.loc, expr.name);
}

Lowered FieldLowering::lowerCall(const ast::Expr& expr, Scope& scope) {
    std::vector<Lowered> args;
    for (const auto& operand : expr.operands) args.push_back(lower(*operand, scope));
    if (auto it = functions_.find(expr.name); it != functions_.end()) return callUser(*it->second, expr, std::move(args));
    if (auto it = context_.maps.find(expr.name); it != context_.maps.end()) return sampleMap(it->second, expr, std::move(args));
    if (findFunction(expr.name)) {
        std::vector<SourceLoc> locs;
        for (const auto& operand : expr.operands) locs.push_back(operand->loc);
        return callBuiltin(expr.name, std::move(args), expr.loc, expr.name, std::move(locs));
    }
    std::vector<std::string_view> known;
    if (errorsStillShown(context_.diagnostics)) {
        for (const FunctionInfo& f : functions()) known.push_back(f.name);
        for (const auto& entry : functions_) known.push_back(entry.first);
        for (const auto& entry : context_.maps) known.push_back(entry.first);
    }
    context_.diagnostics.error("E0002", expr.nameLoc,
                               fmt::format("unknown function '{}'{}", expr.name, didYouMean(expr.name, known)));
    return Lowered::failed();
}

Lowered FieldLowering::callUser(const ast::FunctionDecl& function, const ast::Expr& at, std::vector<Lowered> args) {
    if (function.parameters.size() > size_t(context_.limits.maxParameters)) return Lowered::failed(); // reported
    if (std::find(callStack_.begin(), callStack_.end(), function.name) != callStack_.end()) {
        context_.diagnostics.error("E0013", at.nameLoc,
                                   fmt::format("'{}' calls itself (through {}): functions are inlined, so recursion "
                                               "is not supported",
                                               function.name, fmt::join(callStack_, " -> ")));
        return Lowered::failed();
    }
    if (args.size() != function.parameters.size()) {
        context_.diagnostics.error("E0006", at.nameLoc,
                                   fmt::format("'{}' takes {} argument{} but {} {} given", function.name,
                                               function.parameters.size(), function.parameters.size() == 1 ? "" : "s",
                                               args.size(), args.size() == 1 ? "was" : "were"),
                                   {{function.loc, "declared here"}});
        return Lowered::failed();
    }
    bool ok = true;
    for (size_t i = 0; i < args.size(); ++i) {
        const ast::Parameter& parameter = function.parameters[i];
        const std::optional<Type> type = parseTypeName(parameter.type);
        if (!args[i].ok || !type) {
            ok = false;
            continue;
        }
        if (args[i].number) {
            args[i] = materialize(args[i], *type, at.operands[i]->loc);
            ok = ok && args[i].ok;
        } else if (args[i].type != *type) {
            context_.diagnostics.error("E0010", at.operands[i]->loc,
                                       fmt::format("argument {} of '{}' is {} but the parameter '{}' is {}", i + 1,
                                                   function.name, typeName(args[i].type), parameter.name,
                                                   typeName(*type)),
                                       {{parameter.loc, "the parameter is declared here"}});
            ok = false;
        }
    }
    if (!ok) return Lowered::failed();
    std::vector<uint32_t> argumentNodes;
    for (const Lowered& arg : args) argumentNodes.push_back(arg.node);
    auto key = std::make_pair(&function, std::move(argumentNodes));
    if (auto it = inlined_.find(key); it != inlined_.end()) return it->second;
    Lowered result = lowerFunctionBody(function, args);
    // A body cut short by the step limit is not memoised: it was not really lowered.
    if (!exhausted()) inlined_.emplace(std::move(key), result);
    return result;
}

Lowered FieldLowering::sampleMap(const std::shared_ptr<const SampledMap>& map, const ast::Expr& at,
                                 std::vector<Lowered> args) {
    if (!map) return Lowered::failed(); // a block with errors: reported there
    if (map->dimensions == 3) return sampleVolume(map, at, std::move(args));
    if (args.size() != 2) {
        context_.diagnostics.error("E0006", at.nameLoc,
                                   fmt::format("'{}' samples the {}'s height map at world (x, z): it takes 2 "
                                               "arguments but {} {} given",
                                               at.name, map->source, args.size(), args.size() == 1 ? "was" : "were"));
        return Lowered::failed();
    }
    bool ok = true;
    for (size_t i = 0; i < args.size(); ++i) {
        if (!args[i].ok) {
            ok = false;
        } else if (args[i].number) {
            args[i] = materialize(args[i], Type::Float, at.operands[i]->loc);
            ok = ok && args[i].ok;
        } else if (args[i].type != Type::Float) {
            context_.diagnostics.error("E0010", at.operands[i]->loc,
                                       fmt::format("argument {} of '{}' is {} but a world coordinate is float", i + 1,
                                                   at.name, typeName(args[i].type)));
            ok = false;
        }
    }
    if (!ok) return Lowered::failed();
    FieldNode node;
    node.kind = FieldNode::Kind::Map;
    node.type = Type::Float;
    node.loc = at.loc;
    node.map = map;
    node.operands = {args[0].node, args[1].node};
    return Lowered::ofNode(dag_.add(node), Type::Float);
}

void FieldLowering::reportArgumentTypes(const FunctionInfo& info, const std::vector<Lowered>& args, SourceLoc loc,
                                        std::string_view surface, const std::vector<SourceLoc>& argLocs) {
    const bool isOperator = surface != info.name;
    const std::string callee = isOperator ? fmt::format("operator '{}'", surface) : fmt::format("'{}'", info.name);
    // The one argument that alone makes the call fit once it has another type is to blame, and
    // those types are what it expects; when several could (vec3 + vec2), the call is.
    if (argLocs.size() == args.size()) {
        const std::vector<std::string_view> names = parameterNames(info.signature);
        std::vector<std::vector<std::string_view>> fixing(args.size());
        size_t culprits = 0;
        for (size_t i = 0; i < args.size(); ++i) {
            for (Type type : kAllTypes) {
                const bool alreadyIs = args[i].number ? type == Type::Float || (type == Type::Int && fitsInt(*args[i].number))
                                                      : type == args[i].type;
                if (!alreadyIs && typeWith(info, args, i, type)) fixing[i].push_back(typeName(type));
            }
            culprits += !fixing[i].empty();
        }
        for (size_t i = 0; i < args.size() && culprits == 1; ++i) {
            const std::vector<std::string_view>& expected = fixing[i];
            if (expected.empty()) continue;
            const std::string which =
                isOperator ? (args.size() == 2 ? (i == 0 ? "the left operand" : "the right operand") : "the operand")
                           : fmt::format("argument {}", i + 1);
            const std::string parameter =
                !isOperator && names.size() == args.size() ? fmt::format(" ('{}')", names[i]) : std::string();
            const std::string found =
                args[i].number ? fmt::format("{} literal {}", fitsInt(*args[i].number) ? "an int" : "a float",
                                             formatNumber(*args[i].number))
                               : fmt::format("{}", typeName(args[i].type));
            context_.diagnostics.error("E0010", argLocs[i],
                                       fmt::format("{}{} of {} must be {}, found {}", which, parameter, callee,
                                                   fmt::join(expected, " or "), found),
                                       {{{}, std::string(info.signature)}});
            return;
        }
    }
    context_.diagnostics.error("E0010", loc, fmt::format("{} cannot take ({}); {}", callee, typeList(args), info.signature));
}

// `NAME(p)` of a mesh block: p a vec3 world position, split into its components, which are the
// node's three operands.
Lowered FieldLowering::sampleVolume(const std::shared_ptr<const SampledMap>& map, const ast::Expr& at,
                                    std::vector<Lowered> args) {
    if (args.size() != 1) {
        context_.diagnostics.error("E0006", at.nameLoc,
                                   fmt::format("'{}' samples the {}'s signed distance at a world position (a vec3, "
                                               "e.g. wp): it takes 1 argument but {} were given",
                                               at.name, map->source, args.size()));
        return Lowered::failed();
    }
    if (!args[0].ok) return Lowered::failed();
    if (args[0].number || args[0].type != Type::Vec3) {
        context_.diagnostics.error("E0010", at.operands[0]->loc,
                                   fmt::format("the argument of '{}' is {} but a world position is vec3", at.name,
                                               args[0].number ? std::string_view("a number") : typeName(args[0].type)));
        return Lowered::failed();
    }
    FieldNode node;
    node.kind = FieldNode::Kind::Map;
    node.type = Type::Float;
    node.loc = at.loc;
    node.map = map;
    for (uint32_t c = 0; c < 3; ++c) {
        FieldNode component;
        component.kind = FieldNode::Kind::Component;
        component.type = Type::Float;
        component.loc = at.operands[0]->loc;
        component.component = c;
        component.operands = {args[0].node};
        node.operands.push_back(dag_.add(component));
    }
    return Lowered::ofNode(dag_.add(node), Type::Float);
}

Lowered FieldLowering::callBuiltin(std::string_view name, std::vector<Lowered> args, SourceLoc loc,
                                   std::string_view surface, std::vector<SourceLoc> argLocs) {
    for (const Lowered& a : args)
        if (!a.ok) return Lowered::failed();
    const FunctionInfo* info = findFunction(name);
    std::vector<Type> types;
    const std::optional<Type> result = typeWith(*info, args, args.size(), std::nullopt, &types);
    if (!result) {
        reportArgumentTypes(*info, args, loc, surface, argLocs);
        return Lowered::failed();
    }
    FieldNode node;
    node.kind = FieldNode::Kind::Call;
    node.type = *result;
    node.loc = loc;
    node.function = uint32_t(info - functions().data());
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i].number) args[i] = materialize(args[i], types[i], loc);
        if (!args[i].ok) return Lowered::failed();
        node.operands.push_back(args[i].node);
    }
    return Lowered::ofNode(dag_.add(node), node.type);
}

} // namespace voxc::check

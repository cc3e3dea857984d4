// The operators of field expressions as builtin records: `a + b` is a call of `add`, `c ? a : b`
// of `select`, and so on (docs/language.md lists the mapping). Each is one IEEE operation
// (or an integer one, wrapping in two's complement as SPIR-V defines it), emitted as the same
// single GLSL operator, so both sides agree bit for bit.
#include "Records.h"

#include <cstdint>

namespace voxc::function_records {

namespace {


// Arithmetic: (T, T) -> T, (V, float) -> V, (float, V) -> V like GLSL; (int, int) -> int when allowed.
template <bool AllowInt>
std::optional<Type> arithmeticRule(std::span<const Type> a) {
    if (a.size() != 2) return std::nullopt;
    if (AllowInt && a[0] == Type::Int && a[1] == Type::Int) return Type::Int;
    if (!isFloatLike(a[0]) || !isFloatLike(a[1])) return std::nullopt;
    if (a[0] == a[1] || a[1] == Type::Float) return a[0];
    if (a[0] == Type::Float) return a[1];
    return std::nullopt;
}
std::optional<Type> negateRule(std::span<const Type> a) {
    if (a.size() == 1 && (isFloatLike(a[0]) || a[0] == Type::Int)) return a[0];
    return std::nullopt;
}
std::optional<Type> orderRule(std::span<const Type> a) { // < <= > >=
    if (a.size() == 2 && a[0] == a[1] && (a[0] == Type::Float || a[0] == Type::Int)) return Type::Bool;
    return std::nullopt;
}
std::optional<Type> equalityRule(std::span<const Type> a) { // == !=
    if (a.size() == 2 && a[0] == a[1] && !isVector(a[0])) return Type::Bool;
    return std::nullopt;
}
std::optional<Type> logicRule(std::span<const Type> a) {
    if (a.size() == 2 && a[0] == Type::Bool && a[1] == Type::Bool) return Type::Bool;
    return std::nullopt;
}
std::optional<Type> notRule(std::span<const Type> a) {
    if (a.size() == 1 && a[0] == Type::Bool) return Type::Bool;
    return std::nullopt;
}
std::optional<Type> selectRule(std::span<const Type> a) {
    if (a.size() == 3 && a[0] == Type::Bool && a[1] == a[2]) return a[1];
    return std::nullopt;
}

// Two's complement wrap-around, defined in C++ through unsigned arithmetic.
int32_t wrap(uint32_t x) { return int32_t(x); }

template <typename FloatOp, typename IntOp>
Value arithmetic(std::span<const Value> a, FloatOp f, IntOp i) {
    if (a[0].type == Type::Int) return Value::makeInt(wrap(i(uint32_t(a[0].i), uint32_t(a[1].i))));
    Value out;
    out.type = componentCount(a[0].type) >= componentCount(a[1].type) ? a[0].type : a[1].type;
    for (int c = 0; c < componentCount(out.type); ++c) {
        const float x = a[0].type == Type::Float ? a[0].v.x : a[0].v[c];
        const float y = a[1].type == Type::Float ? a[1].v.x : a[1].v[c];
        out.v[c] = f(x, y);
    }
    return out;
}

Value add(std::span<const Value> a) {
    return arithmetic(a, [](float x, float y) { return x + y; }, [](uint32_t x, uint32_t y) { return x + y; });
}
Value subtract(std::span<const Value> a) {
    return arithmetic(a, [](float x, float y) { return x - y; }, [](uint32_t x, uint32_t y) { return x - y; });
}
Value multiply(std::span<const Value> a) {
    return arithmetic(a, [](float x, float y) { return x * y; }, [](uint32_t x, uint32_t y) { return x * y; });
}
Value divide(std::span<const Value> a) {
    return arithmetic(a, [](float x, float y) { return x / y; }, [](uint32_t, uint32_t) { return 0u; });
}
Value negate(std::span<const Value> a) {
    if (a[0].type == Type::Int) return Value::makeInt(wrap(0u - uint32_t(a[0].i)));
    Value out = a[0];
    out.v = -out.v;
    return out;
}

// Scalar comparisons of two floats, two ints or (== and != only) two bools.
template <typename Compare>
Value compare(std::span<const Value> a, Compare c) {
    switch (a[0].type) {
    case Type::Int: return Value::makeBool(c(a[0].i, a[1].i));
    case Type::Bool: return Value::makeBool(c(a[0].b, a[1].b));
    default: return Value::makeBool(c(a[0].v.x, a[1].v.x));
    }
}

// GLSL: one parenthesised operator application.
template <const char* Op>
std::string infix(std::span<const std::string> a, std::span<const Type>) {
    return "(" + a[0] + " " + Op + " " + a[1] + ")";
}
template <const char* Op>
std::string prefix(std::span<const std::string> a, std::span<const Type>) {
    return std::string("(") + Op + a[0] + ")";
}
std::string selectGlsl(std::span<const std::string> a, std::span<const Type>) {
    return "(" + a[0] + " ? " + a[1] + " : " + a[2] + ")";
}

constexpr char kPlus[] = "+", kMinus[] = "-", kTimes[] = "*", kOver[] = "/", kLess[] = "<", kLessEqual[] = "<=",
               kGreater[] = ">", kGreaterEqual[] = ">=", kEqual[] = "==", kNotEqual[] = "!=", kAnd[] = "&&",
               kOr[] = "||", kNot[] = "!";

// Vulkan allows division 2.5 ulp; this absolute figure holds for quotients up to about 3 in
// magnitude (lavapipe divides exactly). Non-zero, so constant folding leaves divisions alone.
constexpr float kDivision = 1e-6f;

const FunctionInfo kOperators[] = {
    {"add",
     "add(a: T, b: T) -> T; add(a: V, b: float) -> V; add(a: float, b: V) -> V; add(a: int, b: int) -> int; "
     "written a + b; T = float, vec2, vec3; V = vec2, vec3",
     "a + b (component-wise, a float operand broadcast; int wraps around)", arithmeticRule<true>, add,
     infix<kPlus>, kNone, kExact},
    {"sub",
     "sub(a: T, b: T) -> T; sub(a: V, b: float) -> V; sub(a: float, b: V) -> V; sub(a: int, b: int) -> int; "
     "written a - b; T = float, vec2, vec3; V = vec2, vec3",
     "a - b (component-wise, a float operand broadcast; int wraps around)", arithmeticRule<true>, subtract,
     infix<kMinus>, kNone, kExact},
    {"mul",
     "mul(a: T, b: T) -> T; mul(a: V, b: float) -> V; mul(a: float, b: V) -> V; mul(a: int, b: int) -> int; "
     "written a * b; T = float, vec2, vec3; V = vec2, vec3",
     "a * b (component-wise, a float operand broadcast; int wraps around)", arithmeticRule<true>, multiply,
     infix<kTimes>, kNone, kExact},
    {"div",
     "div(a: T, b: T) -> T; div(a: V, b: float) -> V; div(a: float, b: V) -> V; written a / b; "
     "T = float, vec2, vec3; V = vec2, vec3",
     "a / b (component-wise IEEE division, a float operand broadcast; no int division)", arithmeticRule<false>,
     divide, infix<kOver>, kNone, kDivision},
    {"neg", "neg(a: T) -> T; neg(a: int) -> int; written -a; T = float, vec2, vec3",
     "-a (component-wise; int wraps around)", negateRule, negate, prefix<kMinus>, kNone, kExact},
    {"lt", "lt(a: float, b: float) -> bool; lt(a: int, b: int) -> bool; written a < b", "a < b", orderRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x < y; }); }, infix<kLess>, kNone,
     kExact},
    {"le", "le(a: float, b: float) -> bool; le(a: int, b: int) -> bool; written a <= b", "a <= b", orderRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x <= y; }); }, infix<kLessEqual>,
     kNone, kExact},
    {"gt", "gt(a: float, b: float) -> bool; gt(a: int, b: int) -> bool; written a > b", "a > b", orderRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x > y; }); }, infix<kGreater>,
     kNone, kExact},
    {"ge", "ge(a: float, b: float) -> bool; ge(a: int, b: int) -> bool; written a >= b", "a >= b", orderRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x >= y; }); },
     infix<kGreaterEqual>, kNone, kExact},
    {"eq", "eq(a: float, b: float) -> bool; eq(a: int, b: int) -> bool; eq(a: bool, b: bool) -> bool; written a == b",
     "a == b (IEEE: -0 == 0)", equalityRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x == y; }); }, infix<kEqual>,
     kNone, kExact},
    {"ne", "ne(a: float, b: float) -> bool; ne(a: int, b: int) -> bool; ne(a: bool, b: bool) -> bool; written a != b",
     "a != b", equalityRule,
     [](std::span<const Value> a) { return compare(a, [](auto x, auto y) { return x != y; }); }, infix<kNotEqual>,
     kNone, kExact},
    {"and", "and(a: bool, b: bool) -> bool; written a && b", "a and b", logicRule,
     [](std::span<const Value> a) { return Value::makeBool(a[0].b && a[1].b); }, infix<kAnd>, kNone, kExact},
    {"or", "or(a: bool, b: bool) -> bool; written a || b", "a or b", logicRule,
     [](std::span<const Value> a) { return Value::makeBool(a[0].b || a[1].b); }, infix<kOr>, kNone, kExact},
    {"not", "not(a: bool) -> bool; written !a", "not a", notRule,
     [](std::span<const Value> a) { return Value::makeBool(!a[0].b); }, prefix<kNot>, kNone, kExact},
    {"select",
     "select(c: bool, a: T, b: T) -> T; written c ? a : b; T = float, int, bool, vec2, vec3",
     "a where c holds, else b (both are evaluated)", selectRule,
     [](std::span<const Value> a) { return a[0].b ? a[1] : a[2]; }, selectGlsl, kNone, kExact},
};

} // namespace

std::span<const FunctionInfo> operatorFunctions() { return kOperators; }

} // namespace voxc::function_records

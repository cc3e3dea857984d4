#include "voxc/generators/lsystem/Definition.h"

#include <cctype>
#include <cmath>
#include <fmt/format.h>

namespace voxc::lsystem {

std::string_view symbolTypeName(SymbolType type) {
    switch (type) {
    case SymbolType::None: return "none";
    case SymbolType::Tunnel: return "tunnel";
    case SymbolType::Room: return "room";
    }
    return "none";
}

std::optional<SymbolType> parseSymbolType(std::string_view name) {
    if (name == "none") return SymbolType::None;
    if (name == "tunnel") return SymbolType::Tunnel;
    if (name == "room") return SymbolType::Room;
    return std::nullopt;
}

bool ConstrainedMode::contains(glm::dvec3 p) const {
    if (shape == Shape::Sphere) {
        const glm::dvec3 d = p - center;
        return d.x * d.x + d.y * d.y + d.z * d.z <= radius * radius;
    }
    return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
}

LimitError::LimitError(std::string limitName, uint64_t amountNeeded, uint64_t capValue, std::string detail,
                       std::string_view owner)
    : UserError(fmt::format("{}: {} ({}::{} is {})", detail, amountNeeded, owner, limitName, capValue)),
      limit(std::move(limitName)), amount(amountNeeded), cap(capValue) {}

bool isThesisSymbol(char c) {
    switch (c) {
    case 'F': case 'R': case 'L': case 'U': case 'D': case 'O': case 'A': case 'B': case 'S':
    case 'Z': case '0': case '[': case ']':
        return true;
    default:
        return false;
    }
}

bool isTurtleSymbol(TurtleKind kind, char c) {
    if (kind == TurtleKind::Thesis) return isThesisSymbol(c);
    switch (c) {
    case 'F': case 'f': case '+': case '-': case '&': case '^': case '\\': case '/': case '|': case '[': case ']':
        return true;
    default:
        return false;
    }
}

namespace {

// Printable ASCII except blanks: symbols are single visible characters.
bool isSymbolCharacter(char c) { return c > ' ' && c < 127; }

std::string describe(char c) {
    if (isSymbolCharacter(c)) return fmt::format("'{}'", c);
    return fmt::format("byte 0x{:02x}", uint8_t(c));
}

void checkRange(std::vector<DefinitionProblem>& problems, const char* key, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi))
        problems.push_back({key, "E0007", fmt::format("'{}' is {}, outside [{}, {}]", key, value, lo, hi)});
}

// Coordinates beyond this are rejected so positions stay far from overflow after 2^24 steps.
constexpr double kMaxCoordinate = 1e7;

void checkAlternatives(std::vector<DefinitionProblem>& problems, const Definition& definition, char symbol,
                       const std::vector<Alternative>& alternatives, StringRole role) {
    const std::string what = fmt::format("{} {}", role == StringRole::Production ? "production" : "macro", symbol);
    if (alternatives.empty()) problems.push_back({what, "E0009", fmt::format("{} has no alternatives", what)});
    if (alternatives.size() > definition.limits.maxAlternatives)
        problems.push_back({what, "E0012",
                            fmt::format("{} has {} alternatives (Limits::maxAlternatives is {})", what,
                                        alternatives.size(), definition.limits.maxAlternatives)});
    for (size_t i = 0; i < alternatives.size(); ++i) {
        const std::string where = fmt::format("{} #{}", what, i + 1);
        if (!std::isfinite(alternatives[i].weight))
            problems.push_back({where, "E0007", fmt::format("{}: the weight is not a finite number", where)});
        if (auto problem = checkString(definition, alternatives[i].text, role))
            problems.push_back({where, problem->code, fmt::format("{}: {}", where, problem->message)});
    }
}

} // namespace

std::optional<StringProblem> checkString(const Definition& definition, std::string_view text, StringRole role) {
    if (text.empty()) return StringProblem{0, "E0009", "the string is empty"};
    std::vector<size_t> open;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '[') {
            open.push_back(i);
        } else if (c == ']') {
            if (open.empty()) return StringProblem{i, "E0001", "']' closes no '['"};
            open.pop_back();
        } else if (!isSymbolCharacter(c)) {
            return StringProblem{i, "E0002", fmt::format("{} is not a symbol", describe(c))};
        } else if (definition.macros.count(c)) {
            if (role == StringRole::Substitute)
                return StringProblem{i, "E0013", fmt::format("macro '{}' inside a substitute string: macros do not nest", c)};
        } else if (definition.turtle == TurtleKind::Thesis && !isThesisSymbol(c)) {
            // The likely slip is the letter's case ('f' for 'F', 'q' for a macro 'Q').
            const char other = char(std::isupper(uint8_t(c)) ? std::tolower(uint8_t(c)) : std::toupper(uint8_t(c)));
            const bool known = other != c && (isThesisSymbol(other) || definition.macros.count(other));
            return StringProblem{i, "E0002",
                                 fmt::format("unknown symbol '{}': not in the thesis alphabet (F R L U D O A B S Z 0 [ ]) "
                                             "and not a declared macro{}",
                                             c, known ? fmt::format("; did you mean '{}'?", other) : "")};
        }
    }
    if (!open.empty()) return StringProblem{open.back(), "E0001", "'[' is never closed"};
    return std::nullopt;
}

std::vector<DefinitionProblem> checkDefinition(const Definition& definition) {
    std::vector<DefinitionProblem> problems;
    const TurtleParams& p = definition.params;
    checkRange(problems, "angle", p.angle, 0, kMaxTurtleAngle);
    checkRange(problems, "step", p.step, 0, kMaxTurtleStep);
    checkRange(problems, "angle_delta", p.angleDelta, 0, kMaxTurtleAngle);
    checkRange(problems, "step_delta", p.stepDelta, 0, kMaxTurtleStep);
    checkRange(problems, "angle_deviation", p.angleDeviation, 0, kMaxTurtleAngle);
    checkRange(problems, "pitch_limit", p.pitchLimit, 0, kMaxTurtlePitch);
    checkRange(problems, "yaw", p.yaw, -360, 360);
    checkRange(problems, "pitch", p.pitch, -360, 360);
    for (int axis = 0; axis < 3; ++axis) checkRange(problems, "start", p.start[axis], -kMaxCoordinate, kMaxCoordinate);

    const Limits& limits = definition.limits;
    if (limits.maxSymbols > (uint64_t(1) << 32))
        problems.push_back({"limits", "E0012", "Limits::maxSymbols may not exceed 2^32 (hash keys are 32-bit)"});
    if (definition.expansions > limits.maxExpansions)
        problems.push_back({"expansions", "E0012",
                            fmt::format("{} expansions (Limits::maxExpansions is {})", definition.expansions,
                                        limits.maxExpansions)});

    if (auto problem = checkString(definition, definition.axiom, StringRole::Axiom))
        problems.push_back({"axiom", problem->code, fmt::format("axiom: {}", problem->message)});
    for (const auto& [symbol, alternatives] : definition.productions) {
        const std::string where = fmt::format("production {}", symbol);
        if (symbol == '[' || symbol == ']')
            problems.push_back({where, "E0003", "brackets cannot be rewritten"});
        else if (definition.macros.count(symbol))
            problems.push_back({where, "E0003", fmt::format("'{}' is a macro; a production for it would never apply", symbol)});
        checkAlternatives(problems, definition, symbol, alternatives, StringRole::Production);
    }
    for (const auto& [symbol, alternatives] : definition.macros) {
        if (isTurtleSymbol(definition.turtle, symbol))
            problems.push_back({fmt::format("macro {}", symbol), "E0003",
                                fmt::format("'{}' is a turtle symbol and cannot name a macro", symbol)});
        checkAlternatives(problems, definition, symbol, alternatives, StringRole::Substitute);
    }

    if (definition.target) {
        for (int axis = 0; axis < 3; ++axis)
            checkRange(problems, "target.point", definition.target->point[axis], -kMaxCoordinate, kMaxCoordinate);
        checkRange(problems, "target.strength", definition.target->strength, -1e3, 1e3);
    }
    if (definition.balanced) checkRange(problems, "balanced.delta", definition.balanced->delta, 0, 1e3);
    if (const auto& c = definition.constrained) {
        if (c->shape == ConstrainedMode::Shape::Box) {
            for (int axis = 0; axis < 3; ++axis) {
                checkRange(problems, "constrain.min", c->min[axis], -kMaxCoordinate, kMaxCoordinate);
                checkRange(problems, "constrain.max", c->max[axis], c->min[axis], kMaxCoordinate);
            }
        } else {
            for (int axis = 0; axis < 3; ++axis)
                checkRange(problems, "constrain.center", c->center[axis], -kMaxCoordinate, kMaxCoordinate);
            checkRange(problems, "constrain.radius", c->radius, 0, kMaxCoordinate);
        }
    }
    return problems;
}

void requireValid(const Definition& definition) {
    const std::vector<DefinitionProblem> problems = checkDefinition(definition);
    if (problems.empty()) return;
    std::string text = "invalid L-system definition:";
    for (const DefinitionProblem& problem : problems) text += fmt::format("\n  {} {}", problem.code, problem.message);
    throw UserError(text);
}

} // namespace voxc::lsystem

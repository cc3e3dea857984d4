#include "voxc/generators/lsystem/Turtle.h"

#include "voxc/generators/lsystem/Selection.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace voxc::lsystem {

namespace {

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// [H L U] <- [H L U] * R for ABOP's R_U, R_L, R_H (column vectors; docs/architecture.md "Alphabets").
void rotateAboutUp(TurtleState& s, double a) {
    const double c = std::cos(a), n = std::sin(a);
    const glm::dvec3 h = s.heading * c - s.left * n, l = s.heading * n + s.left * c;
    s.heading = h, s.left = l;
}
void rotateAboutLeft(TurtleState& s, double a) {
    const double c = std::cos(a), n = std::sin(a);
    const glm::dvec3 h = s.heading * c + s.up * n, u = -s.heading * n + s.up * c;
    s.heading = h, s.up = u;
}
void rotateAboutHeading(TurtleState& s, double a) {
    const double c = std::cos(a), n = std::sin(a);
    const glm::dvec3 l = s.left * c + s.up * n, u = -s.left * n + s.up * c;
    s.left = l, s.up = u;
}

void clampPitch(const TurtleParams& params, TurtleState& s) {
    if (params.pitchLimit > 0) s.pitch = std::clamp(s.pitch, -params.pitchLimit, params.pitchLimit);
}

TurtleAction move(TurtleKind kind, TurtleState& s, TurtleAction action) {
    if (!(s.step > 0)) return TurtleAction::None;
    s.position += s.step * headingOf(kind, s);
    return action;
}

TurtleAction applyThesis(const TurtleParams& params, TurtleState& s, char c, double turn) {
    switch (c) {
    case 'F': return move(TurtleKind::Thesis, s, TurtleAction::Draw);
    case 'R': s.yaw += turn; break;
    case 'L': s.yaw -= turn; break;
    case 'U': s.pitch += turn; clampPitch(params, s); break;
    case 'D': s.pitch -= turn; clampPitch(params, s); break;
    case 'O': s.angle = std::min(s.angle + params.angleDelta, 180.0); break;
    case 'A': s.angle = std::max(s.angle - params.angleDelta, 0.0); break;
    case 'B': s.step += params.stepDelta; break;
    case 'S': s.step = std::max(s.step - params.stepDelta, 0.0); break;
    case '0': s.noConnect = true; break;
    case '[': return TurtleAction::Push;
    case ']': return TurtleAction::Pop;
    default: break; // Z and macros draw nothing
    }
    return TurtleAction::None;
}

TurtleAction applyAbop(TurtleState& s, char c, double turn) {
    const double a = radians(turn);
    switch (c) {
    case 'F': return move(TurtleKind::Abop, s, TurtleAction::Draw);
    case 'f': return move(TurtleKind::Abop, s, TurtleAction::Move);
    case '+': rotateAboutUp(s, a); break;
    case '-': rotateAboutUp(s, -a); break;
    case '&': rotateAboutLeft(s, a); break;
    case '^': rotateAboutLeft(s, -a); break;
    case '\\': rotateAboutHeading(s, a); break;
    case '/': rotateAboutHeading(s, -a); break;
    case '|': rotateAboutUp(s, std::numbers::pi); break;
    case '[': return TurtleAction::Push;
    case ']': return TurtleAction::Pop;
    default: break; // variables
    }
    return TurtleAction::None;
}

bool isMoveSymbol(TurtleKind kind, char c) { return c == 'F' || (kind == TurtleKind::Abop && c == 'f'); }

} // namespace

TurtleState initialState(const Definition& definition) {
    const TurtleParams& p = definition.params;
    TurtleState s;
    s.position = p.start;
    s.angle = p.angle;
    s.step = p.step;
    s.yaw = p.yaw;
    s.pitch = p.pitch;
    clampPitch(p, s);
    // The abop frame starts at the same yaw and pitch: yaw about U, then pitch up about L.
    rotateAboutUp(s, radians(p.yaw));
    rotateAboutLeft(s, radians(p.pitch));
    return s;
}

glm::dvec3 headingOf(TurtleKind kind, const TurtleState& s) {
    if (kind == TurtleKind::Abop) return s.heading;
    const double psi = radians(s.yaw), theta = radians(s.pitch);
    return {std::cos(theta) * std::cos(psi), std::sin(theta), std::cos(theta) * std::sin(psi)};
}

bool isTurn(TurtleKind kind, char c) {
    if (kind == TurtleKind::Thesis) return c == 'R' || c == 'L' || c == 'U' || c == 'D';
    return c == '+' || c == '-' || c == '&' || c == '^' || c == '\\' || c == '/';
}

TurtleAction applySymbol(const Definition& definition, TurtleState& state, char c, double turnAngle) {
    if (definition.turtle == TurtleKind::Abop) return applyAbop(state, c, turnAngle);
    return applyThesis(definition.params, state, c, turnAngle);
}

double Radii::of(SymbolType type) const {
    switch (type) {
    case SymbolType::Tunnel: return tunnel;
    case SymbolType::Room: return room;
    case SymbolType::None: break;
    }
    return none;
}

Skeleton interpret(const Definition& definition, std::string_view symbols, std::span<const SymbolType> types,
                   const Radii& radii) {
    VOXC_ASSERT(types.empty() || types.size() == symbols.size());
    const TurtleKind kind = definition.turtle;
    const uint64_t moves = uint64_t(std::count_if(symbols.begin(), symbols.end(), [&](char c) { return isMoveSymbol(kind, c); }));
    if (moves > definition.limits.maxSegments)
        throw LimitError("maxSegments", moves, definition.limits.maxSegments, "the skeleton would have up to this many segments");

    Skeleton skeleton;
    skeleton.branches.push_back({});
    TurtleState state = initialState(definition);
    skeleton.finalPosition = state.position;
    const auto& volume = definition.constrained;
    if (volume && !volume->contains(state.position)) {
        skeleton.startOutside = true;
        return skeleton;
    }
    skeleton.segments.reserve(size_t(moves));

    auto leaf = [&] {
        if (state.lastMove && !state.noConnect) skeleton.endpoints.push_back({state.position, state.branch});
    };
    std::vector<TurtleState> stack;
    bool cut = false;     // constrained mode: skipping the rest of the current frame
    size_t skipDepth = 0; // brackets opened while skipping
    const double deviation = definition.params.angleDeviation;
    for (size_t i = 0; i < symbols.size(); ++i) {
        const char c = symbols[i];
        if (cut && c == '[') {
            ++skipDepth;
            continue;
        }
        if (c == ']') {
            if (cut && skipDepth > 0) {
                --skipDepth;
                continue;
            }
            if (stack.empty()) throw UserError(fmt::format("L-system string: ']' at index {} closes no '['", i));
            if (!cut) leaf();
            cut = false;
            state = stack.back();
            stack.pop_back();
            state.lastMove = false; // the parent now sits on a branch point
            continue;
        }
        if (cut) continue;
        if (c == '[') {
            if (stack.size() == definition.limits.maxDepth)
                throw LimitError("maxDepth", stack.size() + 1, definition.limits.maxDepth,
                                 fmt::format("brackets nest this deep at index {}", i));
            stack.push_back(state);
            const uint32_t parent = state.branch;
            state.branch = uint32_t(skeleton.branches.size());
            state.lastMove = false;
            skeleton.branches.push_back({parent, state.noConnect, false});
            continue;
        }
        double turn = state.angle;
        if (deviation > 0 && isTurn(kind, c))
            turn += deviation * (2.0 * uniform({definition.seed, Stream::Jitter, 0, uint32_t(i), 0}) - 1.0);
        const glm::dvec3 from = state.position;
        const TurtleAction action = applySymbol(definition, state, c, turn);
        if (kind == TurtleKind::Thesis && c == '0') skeleton.branches[state.branch].noConnect = true;
        if (action != TurtleAction::Draw && action != TurtleAction::Move) continue;
        if (volume && !volume->contains(state.position)) {
            state.position = from;
            leaf();
            skeleton.branches[state.branch].cut = true;
            cut = true;
            skipDepth = 0;
            continue;
        }
        state.lastMove = action == TurtleAction::Draw;
        if (action == TurtleAction::Draw) {
            const SymbolType type = types.empty() ? SymbolType::None : types[i];
            skeleton.segments.push_back({from, state.position, state.branch, type, radii.of(type)});
        }
    }
    if (!cut) leaf();
    skeleton.finalPosition = state.position;
    return skeleton;
}

} // namespace voxc::lsystem

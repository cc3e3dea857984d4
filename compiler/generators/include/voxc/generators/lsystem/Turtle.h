#pragma once
// The turtle that turns an expanded string into a skeleton (docs/architecture.md, "Turtle to
// skeleton"): segments with their branch, type and radius, the leaf endpoints that branch
// connection joins, and the branches with their "do not connect" flag.
#include "voxc/generators/lsystem/Definition.h"

#include <glm/vec3.hpp>
#include <span>
#include <string_view>
#include <vector>

namespace voxc::lsystem {

struct TurtleState {
    glm::dvec3 position{0.0};
    double yaw = 0.0, pitch = 0.0; // thesis turtle, degrees
    glm::dvec3 heading{1, 0, 0}, left{0, 0, -1}, up{0, 1, 0}; // abop turtle, H x L = U
    double angle = 45.0, step = 4.0;
    bool noConnect = false;
    bool lastMove = false; // the last event of this frame was a drawn move (the leaf rule)
    uint32_t branch = 0;
};

TurtleState initialState(const Definition& definition);
glm::dvec3 headingOf(TurtleKind kind, const TurtleState& state);

// Whether `c` turns the turtle by its angle (and so takes the angle deviation).
bool isTurn(TurtleKind kind, char c);

enum class TurtleAction : uint8_t { None, Draw, Move, Push, Pop };

// Applies one symbol other than a bracket: turns by `turnAngle` (degrees; the caller adds the
// deviation), changes the angle or step, or moves (position updated; Draw for F, Move for abop's
// f; a zero step does not move and returns None). Brackets return Push/Pop and change nothing:
// the caller owns the stack.
TurtleAction applySymbol(const Definition& definition, TurtleState& state, char c, double turnAngle);

struct Segment {
    glm::dvec3 from{0.0}, to{0.0};
    uint32_t branch = 0;
    SymbolType type = SymbolType::None;
    double radius = 0.0;
};

struct Endpoint {
    glm::dvec3 position{0.0};
    uint32_t branch = 0;
};

struct Branch {
    uint32_t parent = 0; // the trunk (branch 0) is its own parent
    bool noConnect = false;
    bool cut = false; // constrained mode ended it at the volume's edge
};

// A line of structural points joining endpoints[from] and endpoints[to] (Connect.h).
struct Connection {
    uint32_t from = 0, to = 0;
    std::vector<glm::dvec3> points; // points.front() and points.back() are exactly the endpoints
};

struct Skeleton {
    std::vector<Segment> segments;
    std::vector<Endpoint> endpoints; // leaves that may be connected, in interpretation order
    std::vector<Branch> branches;
    std::vector<Connection> connections; // filled by connectBranches
    glm::dvec3 finalPosition{0.0};
    bool startOutside = false; // constrained mode: the start lies outside the volume, nothing drawn
};

// Tunnel radius per segment type (voxels); rooms get their width from their branches.
struct Radii {
    double none = 6.0, tunnel = 6.0, room = 6.0;
    double of(SymbolType type) const;
};

// Interprets `symbols` (types: one per symbol, or empty for all None). The segment count is
// bounded by the count of moves before any segment is stored (LimitError "maxSegments").
Skeleton interpret(const Definition& definition, std::string_view symbols, std::span<const SymbolType> types = {},
                   const Radii& radii = {});

} // namespace voxc::lsystem

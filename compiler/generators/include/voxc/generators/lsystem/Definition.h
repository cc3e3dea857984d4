#pragma once
// The host-side model of an L-system cave network (Mark & Berechet 2014; docs/architecture.md,
// "The model"): axiom, weighted productions, typed macros with weighted substitutes, the turtle's
// alphabet and parameters, the selection rule, the generation modes and every bound the expansion
// obeys.
// Angles are in degrees, lengths in voxels; y is up.
#include "voxc/core/Errors.h"
#include "voxc/core/SourceLoc.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace voxc::lsystem {

// The rule file's Type field; the balanced mode pushes choices between tunnels and rooms.
enum class SymbolType : uint8_t { None, Tunnel, Room };

std::string_view symbolTypeName(SymbolType type);
std::optional<SymbolType> parseSymbolType(std::string_view name);

// `thesis`: Table II (F R L U D O A B S Z 0 [ ]) on a yaw/pitch turtle; every other symbol must be
// a macro. `abop`: ABOP's F f + - & ^ \ / | [ ] on a rotating H/L/U frame; every other symbol is a
// plain variable.
enum class TurtleKind : uint8_t { Thesis, Abop };

// `weighted`: P(i) proportional to max(w_i, 0). `thesis`: argmax(u_i + w_i), u_i uniform in [0, 1).
enum class Selection : uint8_t { Weighted, Thesis };

// One weighted alternative: a production's right-hand side or a macro's substitute string.
struct Alternative {
    Alternative() = default;
    Alternative(std::string text_, SymbolType type_, double weight_, SourceLoc loc_ = {})
        : text(std::move(text_)), type(type_), weight(weight_), loc(loc_) {}

    std::string text;
    SymbolType type = SymbolType::None;
    double weight = 1.0;
    SourceLoc loc; // where `text` starts in its source (line 0: none), for located diagnostics
};

struct TurtleParams {
    double angle = 45.0;         // alpha_0, degrees, in [0, 180]
    double step = 4.0;           // s_0, voxels
    double angleDelta = 5.0;     // what O/A add to or take from alpha
    double stepDelta = 1.0;      // what B/S add to or take from s
    double angleDeviation = 0.0; // each turn uses alpha + deviation * (2u - 1)
    double pitchLimit = 0.0;     // > 0: |pitch| <= pitchLimit after every U/D (thesis turtle)
    glm::dvec3 start{0.0};
    double yaw = 0.0;   // 0 = +x, 90 = +z (R turns clockwise seen from +y)
    double pitch = 0.0; // elevation above the x-z plane
};

// Target mode: choices are biased toward `point` (docs/architecture.md, "Modes").
struct TargetMode {
    glm::dvec3 point{0.0};
    double strength = 1.0;
};

// Balanced mode: each tunnel chosen favours rooms by `delta` and each room favours tunnels.
struct BalancedMode {
    double delta = 0.25;
};

// Constrained mode: branches leaving the box or sphere (boundary inclusive) are cut there.
struct ConstrainedMode {
    enum class Shape : uint8_t { Box, Sphere } shape = Shape::Box;
    glm::dvec3 min{0.0}, max{0.0}; // box
    glm::dvec3 center{0.0};        // sphere
    double radius = 0.0;
    bool contains(glm::dvec3 p) const;
};

// Every bound of expansion and interpretation; all are checked before the work they bound.
struct Limits {
    uint32_t maxExpansions = 16;
    uint64_t maxSymbols = uint64_t(1) << 24;  // expanded string length (predicted before allocating)
    uint64_t maxSegments = uint64_t(1) << 22; // skeleton segments, connection polylines included
    uint32_t maxAlternatives = 256;           // productions of one symbol, substitutes of one macro
    uint32_t maxDepth = 4096;                 // bracket nesting (each level holds one turtle state)
};

struct Definition {
    TurtleKind turtle = TurtleKind::Thesis;
    Selection selection = Selection::Weighted;
    std::string axiom = "Z";
    uint32_t expansions = 1;
    uint32_t seed = 0;
    std::map<char, std::vector<Alternative>> productions;
    std::map<char, std::vector<Alternative>> macros;
    TurtleParams params;
    std::optional<TargetMode> target;
    std::optional<BalancedMode> balanced;
    std::optional<ConstrainedMode> constrained;
    Limits limits;
};

// The expansion or interpretation would pass a bound: names it, with the predicted amount.
struct LimitError : UserError {
    // `owner` names the struct that holds the cap, so the message says where to raise it.
    LimitError(std::string limit, uint64_t amount, uint64_t cap, std::string detail, std::string_view owner = "Limits");
    std::string limit; // "maxSymbols", "maxExpansions", "maxSegments", "maxDepth", "maxCentres", ...
    uint64_t amount;   // what the work would need (saturated at UINT64_MAX)
    uint64_t cap;
};

// What is wrong in one string of a definition, at a character offset, with a stable code
// (E0001 unbalanced bracket, E0002 unknown symbol, E0009 empty, E0013 a macro inside a
// substitute). Callers turn `offset` into a source location.
struct StringProblem {
    size_t offset = 0;
    std::string code;
    std::string message;
};

enum class StringRole : uint8_t { Axiom, Production, Substitute };

// Checks one string against the turtle's alphabet and the declared macros.
std::optional<StringProblem> checkString(const Definition& definition, std::string_view text, StringRole role);

// A definition-level problem: `where` names the parameter, production or macro ("angle",
// "production Z #2", "macro Q").
struct DefinitionProblem {
    std::string where;
    std::string code;
    std::string message;
};

// The turtle's parameter ranges checkDefinition holds them to (the viewer's sliders take them too):
// angles in degrees, steps in voxels.
constexpr double kMaxTurtleAngle = 180;   // angle, angle_delta, angle_deviation
constexpr double kMaxTurtlePitch = 90;    // pitch_limit
constexpr double kMaxTurtleStep = 1e4;    // step, step_delta

// Every problem of the definition: parameters out of range (E0007), empty or malformed strings,
// productions for brackets or macros (E0003), weights that are not finite (E0007), too many
// alternatives or expansions (E0012). Empty when the definition can be expanded.
std::vector<DefinitionProblem> checkDefinition(const Definition& definition);

// Throws UserError listing the problems of checkDefinition, if any.
void requireValid(const Definition& definition);

bool isThesisSymbol(char c);
bool isTurtleSymbol(TurtleKind kind, char c);

} // namespace voxc::lsystem

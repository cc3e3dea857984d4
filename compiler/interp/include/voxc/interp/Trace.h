#pragma once
// Rule firings as events, so `voxc interp --trace` and the tests can watch the derivation
// anchor by anchor, and a filter that picks the events a user asked for.
#include "voxc/program/Program.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace voxc {

struct TraceEvent {
    uint32_t grammar = 0;   // index in Program::grammars
    uint32_t iteration = 0;
    uint32_t sweep = 0;     // index in orderSweeps(grammar)
    uint32_t phase = 0;
    glm::ivec3 anchor{0};   // grid-local minimum corner of the window
    uint32_t rule = 0;      // index in Grammar::rules
};

// Every field that is set must match; an unset field accepts everything.
struct TraceFilter {
    struct AnchorBox {
        glm::ivec3 min{0}; // half-open, grid-local
        glm::ivec3 max{0};
    };
    // Rule name, in any grammar unless `grammar` is set: a written rule's name matches the rule and
    // every variant its `symmetry` made (`chip` matches `chip@rot90y`); `chip@rot90y` that variant alone.
    std::optional<std::string> rule;
    std::optional<std::string> grammar; // grammar name
    std::optional<uint32_t> iteration;
    std::optional<AnchorBox> anchors;
};

bool traceFilterAccepts(const Program& program, const TraceFilter& filter, const TraceEvent& event);

// Whether a filter's rule name picks the rule named `ruleName` (see TraceFilter::rule).
bool ruleFilterMatches(std::string_view filterName, std::string_view ruleName);

// UserError when the filter names a grammar, or a rule (of that grammar when it names one), that
// the program does not have, so a misspelt filter is never "0 firings"; the message lists the
// names there are, with a "did you mean".
void checkTraceFilter(const Program& program, const TraceFilter& filter);

// One line, e.g. "iter 0 sweep 0 phase 4 anchor (3,10,0) grammar overhang rule erode_base".
std::string formatTraceEvent(const Program& program, const TraceEvent& event);

} // namespace voxc

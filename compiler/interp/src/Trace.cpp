#include "voxc/interp/Trace.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc {

bool traceFilterAccepts(const Program& program, const TraceFilter& filter, const TraceEvent& event) {
    VOXC_ASSERT(event.grammar < program.grammars.size());
    const Grammar& grammar = program.grammars[event.grammar];
    VOXC_ASSERT(event.rule < grammar.rules.size());
    if (filter.grammar && *filter.grammar != grammar.name) return false;
    if (filter.rule && *filter.rule != grammar.rules[event.rule].name) return false;
    if (filter.iteration && *filter.iteration != event.iteration) return false;
    if (filter.anchors) {
        for (int axis = 0; axis < 3; ++axis) {
            const int a = event.anchor[axis];
            if (a < filter.anchors->min[axis] || a >= filter.anchors->max[axis]) return false;
        }
    }
    return true;
}

std::string formatTraceEvent(const Program& program, const TraceEvent& event) {
    VOXC_ASSERT(event.grammar < program.grammars.size());
    const Grammar& grammar = program.grammars[event.grammar];
    VOXC_ASSERT(event.rule < grammar.rules.size());
    return fmt::format("iter {} sweep {} phase {} anchor ({},{},{}) grammar {} rule {}", event.iteration, event.sweep,
                       event.phase, event.anchor.x, event.anchor.y, event.anchor.z, grammar.name,
                       grammar.rules[event.rule].name);
}

} // namespace voxc

#include "voxc/interp/Trace.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Suggest.h"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

namespace voxc {

bool traceFilterAccepts(const Program& program, const TraceFilter& filter, const TraceEvent& event) {
    VOXC_ASSERT(event.grammar < program.grammars.size());
    const Grammar& grammar = program.grammars[event.grammar];
    VOXC_ASSERT(event.rule < grammar.rules.size());
    if (filter.grammar && *filter.grammar != grammar.name) return false;
    if (filter.rule && !ruleFilterMatches(*filter.rule, grammar.rules[event.rule].name)) return false;
    if (filter.iteration && *filter.iteration != event.iteration) return false;
    if (filter.anchors) {
        for (int axis = 0; axis < 3; ++axis) {
            const int a = event.anchor[axis];
            if (a < filter.anchors->min[axis] || a >= filter.anchors->max[axis]) return false;
        }
    }
    return true;
}

bool ruleFilterMatches(std::string_view filterName, std::string_view ruleName) {
    if (filterName == ruleName) return true;
    // Variants are named WRITTEN@ELEMENT (check/Symmetry.cpp); a name without '@' picks them all.
    return filterName.find('@') == std::string_view::npos && ruleName.size() > filterName.size() &&
           ruleName.starts_with(filterName) && ruleName[filterName.size()] == '@';
}

namespace {

std::string listNames(const std::vector<std::string_view>& names) {
    std::string list;
    for (std::string_view name : names) list += fmt::format("{}{}", list.empty() ? "" : ", ", name);
    return list;
}

} // namespace

void checkTraceFilter(const Program& program, const TraceFilter& filter) {
    std::vector<const Grammar*> grammars;
    if (filter.grammar) {
        std::vector<std::string_view> names;
        for (const Grammar& grammar : program.grammars) {
            if (grammar.name == *filter.grammar) grammars.push_back(&grammar);
            names.push_back(grammar.name);
        }
        if (grammars.empty())
            throw UserError(fmt::format("--trace-grammar '{}': no grammar of that name ({}){}", *filter.grammar,
                                        names.empty() ? std::string("the file declares none")
                                                      : "the grammars are: " + listNames(names),
                                        didYouMean(*filter.grammar, names)));
    } else {
        for (const Grammar& grammar : program.grammars) grammars.push_back(&grammar);
    }
    if (!filter.rule) return;
    std::vector<std::string_view> written; // rule names as written, then every variant's name
    std::vector<std::string_view> variants;
    for (const Grammar* grammar : grammars)
        for (const Rule& rule : grammar->rules) {
            if (ruleFilterMatches(*filter.rule, rule.name)) return;
            const std::string_view name = rule.name;
            const std::string_view base = name.substr(0, name.find('@'));
            if (std::find(written.begin(), written.end(), base) == written.end()) written.push_back(base);
            if (base != name) variants.push_back(name);
        }
    const std::string_view base = std::string_view(*filter.rule).substr(0, filter.rule->find('@'));
    const std::string where = filter.grammar ? fmt::format("grammar '{}'", *filter.grammar) : "any grammar";
    if (base != *filter.rule && std::find(written.begin(), written.end(), base) != written.end()) {
        std::vector<std::string_view> ofRule;
        for (std::string_view variant : variants)
            if (variant.substr(0, variant.find('@')) == base) ofRule.push_back(variant);
        throw UserError(fmt::format("--trace-rule '{}': rule '{}' has no such variant ({}){}", *filter.rule, base,
                                    ofRule.empty() ? std::string("it has no symmetry variants")
                                                   : "its variants are: " + listNames(ofRule),
                                    didYouMean(*filter.rule, ofRule)));
    }
    std::vector<std::string_view> candidates = written;
    candidates.insert(candidates.end(), variants.begin(), variants.end());
    throw UserError(fmt::format("--trace-rule '{}': no rule of that name in {} ({}){}", *filter.rule, where,
                                written.empty() ? std::string("it has no rules") : "the rules are: " + listNames(written),
                                didYouMean(*filter.rule, candidates)));
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

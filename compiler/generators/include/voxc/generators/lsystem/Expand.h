#pragma once
// Expansion: parallel rewriting of the axiom with macros substituted as they are written
// (docs/architecture.md, "Expansion"). Every choice is a hash of (seed, expansion, position,
// occurrence); the length is predicted and capped before any string is allocated.
#include "voxc/generators/lsystem/Definition.h"

#include <string>
#include <vector>

namespace voxc::lsystem {

// One choice among several alternatives (only recorded on request, for traces).
struct Choice {
    uint32_t expansion = 0; // 0: a macro of the axiom, resolved before expansion 1
    uint32_t position = 0;  // index of the rewritten symbol in the string before the pass
    char symbol = 0;        // the rewritten symbol or the macro
    bool macro = false;
    uint32_t alternative = 0; // index among the symbol's productions or the macro's substitutes
};

struct Expansion {
    std::string symbols;
    std::vector<SymbolType> types; // per symbol: the type of the production or substitute that wrote it
    std::vector<uint64_t> lengths; // lengths[k]: after k expansions (lengths[0]: the resolved axiom)
    std::vector<Choice> choices;
};

struct ExpandOptions {
    bool recordChoices = false;
};

// An upper bound on the string's length after each of 0..expansions passes (exact when every
// symbol has at most one production and every macro one substitute; saturates at UINT64_MAX).
std::vector<uint64_t> predictLengths(const Definition& definition, uint32_t expansions);

// An upper bound on the bracket nesting after `expansions` passes: the axiom's (macros counted
// at their deepest substitute) plus, per pass, the deepest nesting one rewrite can add.
uint64_t predictDepth(const Definition& definition, uint32_t expansions);

// Throws LimitError ("maxExpansions", "maxSymbols", "maxDepth") when a predicted length or
// nesting of a valid definition exceeds its limit: the checks expand runs first, without
// expanding (the checker reports them at check time).
void checkExpansionLimits(const Definition& definition);

// Throws UserError for an invalid definition and LimitError ("maxExpansions", "maxSymbols",
// "maxDepth") before allocating when a predicted length or nesting exceeds its limit.
Expansion expand(const Definition& definition, const ExpandOptions& options = {});

} // namespace voxc::lsystem

#pragma once
// Variation of rule sets (docs/architecture.md, "Evolution"): random production rules (§III-B.1),
// crossover by bracket index (§III-D, grammars (7) -> (8)) and mutation (a voxc extension).
// Every operator is a pure function of its inputs and seeds.
#include "voxc/generators/lsystem/Definition.h"

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace voxc::lsystem {

struct RandomRuleParams {
    uint32_t minMacros = 6, maxMacros = 6; // 2 <= min <= max
    double bracketChance = 0.5;
    std::map<char, double> weights;        // per macro; -1 keeps a macro out
    Selection selection = Selection::Weighted;
};

// One random production right side: macros and brackets only, at least one bracket pair,
// balanced, never `[]`, never starting with `[`. Throws UserError for bad parameters.
std::string randomProduction(const RandomRuleParams& params, uint32_t seed, uint32_t rule = 0);

// Brackets of `text` numbered 1.. in the order of their `[` (any depth): the offsets of each
// `[` and its matching `]`. Throws UserError for unbalanced text.
std::vector<std::pair<size_t, size_t>> bracketPairs(std::string_view text);

// Exchanges the contents of bracket i of a and bracket j of b (1-based): returns (a with b's
// content, b with a's content). Throws UserError when an index is out of range.
std::pair<std::string, std::string> crossover(std::string_view a, size_t i, std::string_view b, size_t j);

// Bracket indices drawn from (seed, generation, child); both strings need a bracket.
std::pair<size_t, size_t> randomCrossoverIndices(std::string_view a, std::string_view b, uint32_t seed,
                                                 uint32_t generation, uint32_t child);

enum class MutationKind : uint8_t { SwapMacro, InsertBrackets, DeleteBrackets, PerturbWeight };

struct Mutation {
    MutationKind kind = MutationKind::SwapMacro;
    std::string description;
};

// One mutation of `definition`, drawn from (seed, generation, child) among the kinds that apply:
// replace one macro occurrence of a production by another macro, wrap one symbol of a
// production in a new bracket pair, remove one bracket pair (keeping its content), or move one
// weight (production or substitute) by up to +-kWeightStep. Throws UserError when none applies.
constexpr double kWeightStep = 0.25;
Definition mutate(const Definition& definition, uint32_t seed, uint32_t generation, uint32_t child,
                  Mutation* applied = nullptr);

// `count` children of the picked definitions: child k crosses the first production of picks
// k mod n and (k + 1) mod n at random brackets (when both have one), mutates the result once and
// gets its own seed. With one pick, children are mutations of it.
std::vector<Definition> nextGeneration(const std::vector<Definition>& picks, uint32_t count, uint32_t seed,
                                       uint32_t generation);

} // namespace voxc::lsystem

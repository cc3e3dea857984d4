#include "voxc/generators/lsystem/Evolve.h"

#include "voxc/generators/lsystem/Selection.h"

#include <cmath>
#include <fmt/format.h>

namespace voxc::lsystem {

namespace {

// Random rules longer than this would only be truncated by the expansion limits anyway.
constexpr uint32_t kMaxRandomMacros = 64;

// One production alternative a mutation can edit.
struct Site {
    char symbol;
    size_t alternative;
    size_t offset; // a symbol's offset, or a bracket pair's index
};

} // namespace

std::string randomProduction(const RandomRuleParams& params, uint32_t seed, uint32_t rule) {
    if (params.minMacros < 2 || params.minMacros > params.maxMacros || params.maxMacros > kMaxRandomMacros)
        throw UserError(fmt::format("random rules need 2 <= min <= max <= {} macros, got [{}, {}]", kMaxRandomMacros,
                                    params.minMacros, params.maxMacros));
    if (!(params.bracketChance >= 0 && params.bracketChance <= 1))
        throw UserError(fmt::format("random rules: bracket chance {} is outside [0, 1]", params.bracketChance));
    std::vector<char> macros;
    std::vector<double> weights;
    bool anyIncluded = false;
    for (const auto& [macro, weight] : params.weights) {
        if (!std::isfinite(weight)) throw UserError(fmt::format("random rules: the weight of '{}' is not finite", macro));
        macros.push_back(macro);
        weights.push_back(weight);
        anyIncluded = anyIncluded || weight >= 0;
    }
    if (!anyIncluded) throw UserError("random rules: no macro has a weight >= 0, every macro is excluded");

    auto key = [&](uint32_t k, uint32_t what) { return DrawKey{seed, Stream::RandomRule, rule, k, what}; };
    const uint32_t count = params.minMacros + uniformIndex(key(0, 0), params.maxMacros - params.minMacros + 1);
    std::string text;
    uint32_t depth = 0;
    bool opened = false;
    for (uint32_t k = 0; k < count; ++k) {
        text += macros[choose(params.selection, weights, {}, key(k + 1, 1))];
        if (k + 1 == count) break;
        if (depth > 0 && uniform(key(k + 1, 2)) < params.bracketChance) text += ']', --depth;
        if (uniform(key(k + 1, 3)) < params.bracketChance) text += '[', ++depth, opened = true;
    }
    text.append(depth, ']');
    if (!opened) { // wrap the last macro: ...X -> ...[X]
        const char last = text.back();
        text.back() = '[';
        text += last;
        text += ']';
    }
    return text;
}

std::vector<std::pair<size_t, size_t>> bracketPairs(std::string_view text) {
    std::vector<std::pair<size_t, size_t>> pairs;
    std::vector<size_t> open; // indices into pairs
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '[') {
            open.push_back(pairs.size());
            pairs.push_back({i, i});
        } else if (text[i] == ']') {
            if (open.empty()) throw UserError(fmt::format("'{}': ']' at {} closes no '['", text, i));
            pairs[open.back()].second = i;
            open.pop_back();
        }
    }
    if (!open.empty()) throw UserError(fmt::format("'{}': '[' at {} is never closed", text, pairs[open.back()].first));
    return pairs;
}

std::pair<std::string, std::string> crossover(std::string_view a, size_t i, std::string_view b, size_t j) {
    const auto pa = bracketPairs(a), pb = bracketPairs(b);
    if (i < 1 || i > pa.size() || j < 1 || j > pb.size())
        throw UserError(fmt::format("crossover of bracket {} of '{}' ({} brackets) with bracket {} of '{}' ({} brackets)",
                                    i, a, pa.size(), j, b, pb.size()));
    const auto [ao, ac] = pa[i - 1];
    const auto [bo, bc] = pb[j - 1];
    const std::string_view contentA = a.substr(ao + 1, ac - ao - 1), contentB = b.substr(bo + 1, bc - bo - 1);
    std::string first = std::string(a.substr(0, ao + 1)) + std::string(contentB) + std::string(a.substr(ac));
    std::string second = std::string(b.substr(0, bo + 1)) + std::string(contentA) + std::string(b.substr(bc));
    return {std::move(first), std::move(second)};
}

std::pair<size_t, size_t> randomCrossoverIndices(std::string_view a, std::string_view b, uint32_t seed,
                                                 uint32_t generation, uint32_t child) {
    const size_t na = bracketPairs(a).size(), nb = bracketPairs(b).size();
    if (na == 0 || nb == 0) throw UserError("crossover needs a bracket in both rules");
    const DrawKey key{seed, Stream::Crossover, generation, child, 0};
    return {1 + uniformIndex(key, uint32_t(na), 0), 1 + uniformIndex(key, uint32_t(nb), 1)};
}

Definition mutate(const Definition& definition, uint32_t seed, uint32_t generation, uint32_t child, Mutation* applied) {
    std::vector<Site> swaps, inserts, deletes;
    for (const auto& [symbol, alternatives] : definition.productions)
        for (size_t a = 0; a < alternatives.size(); ++a) {
            const std::string& text = alternatives[a].text;
            for (size_t i = 0; i < text.size(); ++i) {
                if (text[i] == '[' || text[i] == ']') continue;
                inserts.push_back({symbol, a, i});
                if (definition.macros.count(text[i]) && definition.macros.size() >= 2) swaps.push_back({symbol, a, i});
            }
            const size_t pairs = bracketPairs(text).size();
            for (size_t p = 0; p < pairs; ++p) deletes.push_back({symbol, a, p});
        }
    std::vector<std::pair<bool, Site>> weights; // (macro?, site)
    for (const auto& [symbol, alternatives] : definition.productions)
        for (size_t a = 0; a < alternatives.size(); ++a) weights.push_back({false, {symbol, a, 0}});
    for (const auto& [symbol, alternatives] : definition.macros)
        for (size_t a = 0; a < alternatives.size(); ++a) weights.push_back({true, {symbol, a, 0}});

    std::vector<MutationKind> kinds;
    if (!swaps.empty()) kinds.push_back(MutationKind::SwapMacro);
    if (!inserts.empty()) kinds.push_back(MutationKind::InsertBrackets);
    if (!deletes.empty()) kinds.push_back(MutationKind::DeleteBrackets);
    if (!weights.empty()) kinds.push_back(MutationKind::PerturbWeight);
    if (kinds.empty()) throw UserError("nothing to mutate: the L-system has no productions or macros");

    const DrawKey key{seed, Stream::Mutation, generation, child, 0};
    Mutation mutation{kinds[uniformIndex(key, uint32_t(kinds.size()), 0)], ""};
    Definition result = definition;
    auto pick = [&](const auto& sites) { return sites[uniformIndex(key, uint32_t(sites.size()), 1)]; };
    switch (mutation.kind) {
    case MutationKind::SwapMacro: {
        const Site site = pick(swaps);
        std::string& text = result.productions[site.symbol][site.alternative].text;
        std::vector<char> others;
        for (const auto& entry : definition.macros)
            if (entry.first != text[site.offset]) others.push_back(entry.first);
        const char replacement = others[uniformIndex(key, uint32_t(others.size()), 2)];
        mutation.description = fmt::format("production {} #{}: macro '{}' at {} becomes '{}'", site.symbol,
                                           site.alternative + 1, text[site.offset], site.offset, replacement);
        text[site.offset] = replacement;
        break;
    }
    case MutationKind::InsertBrackets: {
        const Site site = pick(inserts);
        std::string& text = result.productions[site.symbol][site.alternative].text;
        mutation.description = fmt::format("production {} #{}: '{}' at {} wrapped in brackets", site.symbol,
                                           site.alternative + 1, text[site.offset], site.offset);
        text.insert(site.offset + 1, 1, ']');
        text.insert(site.offset, 1, '[');
        break;
    }
    case MutationKind::DeleteBrackets: {
        const Site site = pick(deletes);
        std::string& text = result.productions[site.symbol][site.alternative].text;
        const auto [open, close] = bracketPairs(text)[site.offset];
        mutation.description = fmt::format("production {} #{}: bracket {} removed", site.symbol, site.alternative + 1,
                                           site.offset + 1);
        text.erase(close, 1);
        text.erase(open, 1);
        break;
    }
    case MutationKind::PerturbWeight: {
        const auto [macro, site] = pick(weights);
        Alternative& alternative = (macro ? result.macros : result.productions)[site.symbol][site.alternative];
        const double before = alternative.weight;
        alternative.weight += kWeightStep * (2 * uniform(key, 2) - 1);
        mutation.description = fmt::format("{} {} #{}: weight {} -> {}", macro ? "macro" : "production", site.symbol,
                                           site.alternative + 1, before, alternative.weight);
        break;
    }
    }
    if (applied) *applied = std::move(mutation);
    return result;
}

std::vector<Definition> nextGeneration(const std::vector<Definition>& picks, uint32_t count, uint32_t seed,
                                       uint32_t generation) {
    if (picks.empty()) throw UserError("a generation needs at least one pick");
    std::vector<Definition> children;
    for (uint32_t k = 0; k < count; ++k) {
        Definition child = picks[k % picks.size()];
        const Definition& other = picks[(k + 1) % picks.size()];
        if (picks.size() >= 2 && !child.productions.empty() && !other.productions.empty()) {
            std::string& mine = child.productions.begin()->second.front().text;
            const std::string& theirs = other.productions.begin()->second.front().text;
            if (!bracketPairs(mine).empty() && !bracketPairs(theirs).empty()) {
                const auto [i, j] = randomCrossoverIndices(mine, theirs, seed, generation, k);
                mine = crossover(mine, i, theirs, j).first;
                for (const auto& entry : other.macros) child.macros.insert(entry); // macros the graft uses
            }
        }
        child = mutate(child, seed, generation, k);
        child.seed = uint32_t(uniform({seed, Stream::Generation, generation, k, 0}) * 0x1p32);
        children.push_back(std::move(child));
    }
    return children;
}

} // namespace voxc::lsystem

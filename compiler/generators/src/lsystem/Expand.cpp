#include "voxc/generators/lsystem/Expand.h"

#include "voxc/generators/lsystem/Selection.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <limits>

namespace voxc::lsystem {

namespace {

// Symbol counts per distinct symbol of the definition; doubles saturate instead of wrapping.
class LengthModel {
public:
    explicit LengthModel(const Definition& d) : definition_(d) {
        index_.fill(-1);
        auto add = [&](std::string_view text) {
            for (char c : text)
                if (index_[uint8_t(c)] < 0) index_[uint8_t(c)] = int(size_++);
        };
        add(d.axiom);
        for (const auto& [symbol, alternatives] : d.productions) {
            add(std::string_view(&symbol, 1));
            for (const Alternative& a : alternatives) add(a.text);
        }
        for (const auto& [symbol, alternatives] : d.macros) {
            add(std::string_view(&symbol, 1));
            for (const Alternative& a : alternatives) add(a.text);
        }
        image_.assign(size_ * size_, 0.0);
        for (int c = 0; c < 256; ++c) {
            if (index_[c] < 0) continue;
            const auto production = d.productions.find(char(c));
            if (production == d.productions.end()) {
                image_[size_t(index_[c]) * size_ + size_t(index_[c])] = 1;
                continue;
            }
            std::vector<double> worst(size_, 0.0);
            for (const Alternative& a : production->second) maxInto(worst, written(a.text));
            std::copy(worst.begin(), worst.end(), image_.begin() + ptrdiff_t(size_t(index_[c]) * size_));
        }
    }

    // Counts of a string as written: each macro occurrence counts as its largest substitute.
    std::vector<double> written(std::string_view text) const {
        std::vector<double> counts(size_, 0.0);
        for (char c : text) {
            const auto macro = definition_.macros.find(c);
            if (macro == definition_.macros.end()) {
                counts[size_t(index_[uint8_t(c)])] += 1;
                continue;
            }
            std::vector<double> worst(size_, 0.0);
            for (const Alternative& a : macro->second) {
                std::vector<double> one(size_, 0.0);
                for (char s : a.text) one[size_t(index_[uint8_t(s)])] += 1;
                maxInto(worst, one);
            }
            for (size_t t = 0; t < size_; ++t) counts[t] += worst[t];
        }
        return counts;
    }

    std::vector<double> pass(const std::vector<double>& counts) const {
        std::vector<double> next(size_, 0.0);
        for (size_t s = 0; s < size_; ++s)
            if (counts[s] > 0)
                for (size_t t = 0; t < size_; ++t) next[t] = std::min(next[t] + counts[s] * image_[s * size_ + t], kSaturated);
        return next;
    }

    static uint64_t total(const std::vector<double>& counts) {
        double sum = 0;
        for (double c : counts) sum += c;
        return sum >= 0x1p64 ? std::numeric_limits<uint64_t>::max() : uint64_t(sum);
    }

private:
    static constexpr double kSaturated = 1e300;
    static void maxInto(std::vector<double>& into, const std::vector<double>& from) {
        for (size_t t = 0; t < into.size(); ++t) into[t] = std::max(into[t], from[t]);
    }

    const Definition& definition_;
    std::array<int, 256> index_;
    size_t size_ = 0;
    std::vector<double> image_; // image_[s * size_ + t]: most t one rewrite of s can write
};

// One expansion run: the output of the current pass, the modes' running state and the turtle
// that follows the output as it is written (target mode only).
class Expander {
public:
    Expander(const Definition& d, const ExpandOptions& options) : d_(d), options_(options) {
        productionOf_.fill(nullptr);
        macroOf_.fill(nullptr);
        for (const auto& [symbol, alternatives] : d.productions) productionOf_[uint8_t(symbol)] = &alternatives;
        for (const auto& [symbol, alternatives] : d.macros) macroOf_[uint8_t(symbol)] = &alternatives;
    }

    Expansion run(const std::vector<uint64_t>& predicted) {
        Expansion result;
        beginPass(predicted[0]);
        for (size_t i = 0; i < d_.axiom.size(); ++i) {
            const char c = d_.axiom[i];
            if (macroOf_[uint8_t(c)]) writeMacro(c, {d_.seed, Stream::Macro, 0, uint32_t(i), 0});
            else write(c, SymbolType::None);
        }
        result.lengths.push_back(out_.size());
        for (uint32_t k = 1; k <= d_.expansions; ++k) {
            std::string in = std::move(out_);
            std::vector<SymbolType> inTypes = std::move(outTypes_);
            beginPass(predicted[k]);
            for (size_t i = 0; i < in.size(); ++i) {
                if (const auto* productions = productionOf_[uint8_t(in[i])]) rewrite(in[i], *productions, k, uint32_t(i));
                else write(in[i], inTypes[i]);
            }
            result.lengths.push_back(out_.size());
        }
        result.symbols = std::move(out_);
        result.types = std::move(outTypes_);
        result.choices = std::move(choices_);
        return result;
    }

private:
    void beginPass(uint64_t predictedLength) {
        out_.clear();
        outTypes_.clear();
        out_.reserve(size_t(predictedLength));
        outTypes_.reserve(size_t(predictedLength));
        turtle_ = initialState(d_);
        stack_.clear();
    }

    void write(char c, SymbolType type) {
        out_.push_back(c);
        outTypes_.push_back(type);
        if (!d_.target) return;
        const TurtleAction action = applySymbol(d_, turtle_, c, turtle_.angle);
        if (action == TurtleAction::Push) stack_.push_back(turtle_); // depth bounded by predictDepth
        else if (action == TurtleAction::Pop && !stack_.empty()) turtle_ = stack_.back(), stack_.pop_back();
    }

    void rewrite(char symbol, const std::vector<Alternative>& productions, uint32_t k, uint32_t position) {
        const Alternative& chosen = productions[select(symbol, false, productions, {d_.seed, Stream::Production, k, position, 0})];
        uint32_t occurrence = 0;
        for (char c : chosen.text) {
            if (macroOf_[uint8_t(c)]) writeMacro(c, {d_.seed, Stream::Macro, k, position, occurrence++});
            else write(c, chosen.type);
        }
    }

    void writeMacro(char macro, const DrawKey& key) {
        const std::vector<Alternative>& substitutes = *macroOf_[uint8_t(macro)];
        const Alternative& chosen = substitutes[select(macro, true, substitutes, key)];
        for (char c : chosen.text) write(c, chosen.type);
    }

    size_t select(char symbol, bool macro, const std::vector<Alternative>& alternatives, const DrawKey& key) {
        size_t chosen = 0;
        if (alternatives.size() > 1) {
            weights_.clear();
            offsets_.clear();
            for (const Alternative& a : alternatives) {
                weights_.push_back(a.weight);
                offsets_.push_back(offset(a));
            }
            chosen = choose(d_.selection, weights_, offsets_, key);
            if (options_.recordChoices) choices_.push_back({key.step, key.position, symbol, macro, uint32_t(chosen)});
        }
        if (d_.balanced) {
            const SymbolType type = alternatives[chosen].type;
            if (type == SymbolType::Tunnel) balance_ += d_.balanced->delta;
            else if (type == SymbolType::Room) balance_ -= d_.balanced->delta;
        }
        return chosen;
    }

    double offset(const Alternative& a) const {
        double total = 0;
        if (d_.balanced) {
            if (a.type == SymbolType::Room) total += balance_;
            else if (a.type == SymbolType::Tunnel) total -= balance_;
        }
        if (d_.target) total += targetOffset(a.text);
        return total;
    }

    // Target mode: simulate the candidate's stem (top-level brackets skipped, since a pop would
    // restore the state anyway; macros inside a production are no-ops) and score how much it
    // closes the distance to the target and how well its end faces it.
    double targetOffset(std::string_view text) const {
        TurtleState s = turtle_;
        const glm::dvec3 target = d_.target->point;
        double pathLength = 0;
        int depth = 0;
        for (char c : text) {
            if (c == '[') ++depth;
            else if (c == ']') --depth;
            else if (depth == 0) {
                const glm::dvec3 from = s.position;
                if (applySymbol(d_, s, c, s.angle) == TurtleAction::Draw) pathLength += glm::length(s.position - from);
            }
        }
        const double before = glm::length(target - turtle_.position), after = glm::length(target - s.position);
        const double closer = pathLength > 0 ? std::clamp((before - after) / pathLength, -1.0, 1.0) : 0.0;
        const double facing = after > 0 ? glm::dot(headingOf(d_.turtle, s), (target - s.position) / after) : 1.0;
        return d_.target->strength * (closer + facing) / 2;
    }

    const Definition& d_;
    const ExpandOptions& options_;
    std::array<const std::vector<Alternative>*, 256> productionOf_, macroOf_; // by symbol, null if none
    std::string out_;
    std::vector<SymbolType> outTypes_;
    std::vector<Choice> choices_;
    TurtleState turtle_;
    std::vector<TurtleState> stack_;
    double balance_ = 0; // balanced mode: cumulative over the whole expansion
    std::vector<double> weights_, offsets_;
};

// The deepest nesting inside `text` as written, each macro counted at its deepest substitute
// (substitutes hold no macros, so `macros` is null for them).
uint64_t nesting(std::string_view text, const std::map<char, std::vector<Alternative>>* macros) {
    uint64_t depth = 0, deepest = 0;
    for (char c : text) {
        if (c == '[') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']') {
            depth -= depth > 0;
        } else if (macros) {
            if (const auto macro = macros->find(c); macro != macros->end())
                for (const Alternative& a : macro->second) deepest = std::max(deepest, depth + nesting(a.text, nullptr));
        }
    }
    return deepest;
}

} // namespace

uint64_t predictDepth(const Definition& definition, uint32_t expansions) {
    uint64_t perPass = 0;
    for (const auto& [symbol, alternatives] : definition.productions)
        for (const Alternative& a : alternatives) perPass = std::max(perPass, nesting(a.text, &definition.macros));
    return nesting(definition.axiom, &definition.macros) + uint64_t(expansions) * perPass;
}

std::vector<uint64_t> predictLengths(const Definition& definition, uint32_t expansions) {
    const LengthModel model(definition);
    std::vector<double> counts = model.written(definition.axiom);
    std::vector<uint64_t> lengths{LengthModel::total(counts)};
    for (uint32_t k = 1; k <= expansions; ++k) {
        counts = model.pass(counts);
        lengths.push_back(LengthModel::total(counts));
    }
    return lengths;
}

void checkExpansionLimits(const Definition& definition) {
    const Limits& limits = definition.limits;
    if (definition.expansions > limits.maxExpansions)
        throw LimitError("maxExpansions", definition.expansions, limits.maxExpansions, "too many expansions");
    const std::vector<uint64_t> predicted = predictLengths(definition, definition.expansions);
    for (size_t k = 0; k < predicted.size(); ++k)
        if (predicted[k] > limits.maxSymbols)
            throw LimitError("maxSymbols", predicted[k], limits.maxSymbols,
                             fmt::format("the string could reach this many symbols after {} expansion{}", k,
                                         k == 1 ? "" : "s"));
    if (const uint64_t depth = predictDepth(definition, definition.expansions); depth > limits.maxDepth)
        throw LimitError("maxDepth", depth, limits.maxDepth, "brackets could nest this deep");
}

Expansion expand(const Definition& definition, const ExpandOptions& options) {
    if (definition.expansions > definition.limits.maxExpansions)
        throw LimitError("maxExpansions", definition.expansions, definition.limits.maxExpansions,
                         "too many expansions");
    requireValid(definition);
    checkExpansionLimits(definition);
    const std::vector<uint64_t> predicted = predictLengths(definition, definition.expansions);
    Expansion result = Expander(definition, options).run(predicted);
    for (size_t k = 0; k < predicted.size(); ++k) VOXC_ASSERT(result.lengths[k] <= predicted[k]);
    return result;
}

} // namespace voxc::lsystem

#include "voxc/check/FeatureOverrides.h"

#include <algorithm>
#include <fmt/format.h>
#include <utility>
#include <vector>

namespace voxc {

namespace {

size_t offsetOf(const std::vector<size_t>& lineStarts, SourceLoc loc) {
    return lineStarts[std::min<size_t>(loc.line - 1, lineStarts.size() - 1)] + loc.column - 1;
}

std::vector<size_t> lineStartsOf(const std::string& text) {
    std::vector<size_t> starts{0};
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') starts.push_back(i + 1);
    return starts;
}

std::string formatNumber(double value) { return fmt::format("{}", value); }

} // namespace

const ast::Assignment* findAssignment(const ast::Block& block, std::string_view key) {
    for (const ast::Assignment& a : block.assignments)
        if (a.key == key) return &a;
    return nullptr;
}

namespace {

const ast::Block* findBlock(const std::vector<ast::Block>& blocks, std::string_view kind, std::string_view label) {
    for (const ast::Block& block : blocks)
        if (block.kind == kind && block.label == label) return &block;
    return nullptr;
}

// The block an override's name points into and the key: "feature.key", "grammar.key",
// "grammar.rule.key"; nullptr when the file has no such block.
std::pair<const ast::Block*, std::string> keyBlock(const ast::File& file, const std::string& name) {
    const size_t dot = name.find('.');
    const size_t last = name.rfind('.');
    const std::string owner = name.substr(0, dot), key = name.substr(last + 1);
    if (dot == last) {
        for (const ast::FeatureDecl& decl : file.features)
            if (decl.name == owner) return {&decl.body, key};
        return {findBlock(file.blocks, "grammar", owner), key};
    }
    const ast::Block* grammar = findBlock(file.blocks, "grammar", owner);
    return {grammar ? findBlock(grammar->blocks, "rule", name.substr(dot + 1, last - dot - 1)) : nullptr, key};
}

} // namespace

std::string overrideFeatureKeys(const std::string& text, const ast::File& file, const std::map<std::string, double>& overrides) {
    if (overrides.empty()) return text;
    const std::vector<size_t> lineStarts = lineStartsOf(text);
    struct Splice {
        size_t offset, length;
        std::string text;
    };
    std::vector<Splice> splices;
    for (const auto& [name, value] : overrides) {
        if (name.find('.') == std::string::npos) continue;
        const auto [block, key] = keyBlock(file, name);
        if (block == nullptr) continue;
        if (const ast::Assignment* a = findAssignment(*block, key)) {
            if (a->value.scalar && a->value.loc.line > 0)
                splices.push_back({offsetOf(lineStarts, a->value.loc), a->value.loc.length, formatNumber(value)});
        } else if (block->end.line > 0) {
            splices.push_back({offsetOf(lineStarts, block->end), 0, fmt::format("{} = {}; ", key, formatNumber(value))});
        }
    }
    // From the end backwards, so each splice's offset still holds.
    std::sort(splices.begin(), splices.end(), [](const Splice& a, const Splice& b) { return a.offset > b.offset; });
    std::string out = text;
    for (const Splice& splice : splices)
        if (splice.offset + splice.length <= out.size()) out.replace(splice.offset, splice.length, splice.text);
    return out;
}

std::string featureOverrideErrors(const ast::File& file, const std::map<std::string, double>& overrides) {
    std::string errors;
    for (const auto& [name, value] : overrides) {
        const size_t dot = name.find('.');
        const std::string feature = name.substr(0, dot);
        const bool declared = std::any_of(file.features.begin(), file.features.end(),
                                          [&](const ast::FeatureDecl& decl) { return decl.name == feature; });
        if (dot == std::string::npos || dot + 1 == name.size())
            errors += fmt::format("override '{}': a feature key is written FEATURE.KEY\n", name);
        else if (!declared)
            errors += fmt::format("override '{}': the file declares no feature '{}'\n", name, feature);
    }
    return errors;
}

} // namespace voxc

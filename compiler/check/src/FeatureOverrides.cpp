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

// A nested block of `parent` named by one segment of a key's name: its label, its kind when it is
// the only block of that kind there, or KIND[I].
const ast::Block* findMember(const ast::Block& parent, std::string_view segment) {
    for (const ast::Block& member : parent.blocks)
        if (member.label == segment) return &member;
    const size_t open = segment.find('[');
    if (open != std::string_view::npos) {
        if (segment.back() != ']') return nullptr;
        const std::string_view digits = segment.substr(open + 1, segment.size() - open - 2);
        if (digits.empty() || digits.size() > 9 ||
            !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return nullptr;
        size_t index = std::stoul(std::string(digits));
        for (const ast::Block& member : parent.blocks)
            if (member.kind == segment.substr(0, open) && index-- == 0) return &member;
        return nullptr;
    }
    const ast::Block* only = nullptr;
    for (const ast::Block& member : parent.blocks)
        if (member.kind == segment && !member.label) {
            if (only != nullptr) return nullptr;
            only = &member;
        }
    return only;
}

} // namespace

std::optional<KeyTarget> findKeyTarget(const ast::File& file, std::string_view name) {
    const size_t dot = name.find('.');
    const size_t last = name.rfind('.');
    if (dot == std::string_view::npos || last + 1 == name.size()) return std::nullopt;
    const std::string_view owner = name.substr(0, dot);
    const ast::Block* block = nullptr;
    for (const ast::FeatureDecl& decl : file.features)
        if (block == nullptr && decl.name == owner) block = &decl.body;
    for (const ast::Block& top : file.blocks)
        if (block == nullptr && top.label == owner) block = &top;
    for (size_t at = dot + 1; block != nullptr && at <= last;) {
        const size_t next = name.find('.', at); // at most `last`
        block = findMember(*block, name.substr(at, next - at));
        at = next + 1;
    }
    if (block == nullptr) return std::nullopt;
    return KeyTarget{block, std::string(name.substr(last + 1))};
}

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
        const std::optional<KeyTarget> target = findKeyTarget(file, name);
        if (!target) continue;
        const ast::Block* block = target->block;
        const std::string& key = target->key;
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

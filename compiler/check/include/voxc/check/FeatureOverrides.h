#pragma once
// Feature keys set from outside the file, as `voxc view`'s sliders and libvoxc's overrides set
// them: the key's written value is replaced in the text given to the checker (or the key is added
// to the block when the file leaves it to its default), so the checker reads and checks it exactly
// as if the file said so; the file on disk is never written. Constants need no rewriting
// (CheckOptions::constOverrides).
#include "voxc/syntax/Ast.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace voxc {

// The key's assignment in `block`, or null when the block does not write it.
const ast::Assignment* findAssignment(const ast::Block& block, std::string_view key);

// The block a key's name points into, and the key: "OWNER.KEY" or "OWNER.MEMBER. ... .KEY", where
// OWNER is a feature or a labelled top-level block (grammar, curves, terrain, lsystem, ...) and
// each MEMBER a block nested in the one before: by its label ("grammar.rule.probability",
// "valley.river.rain"), by its kind when it is the only unlabelled block of that kind there
// ("valley.noise.amplitude"), or as KIND[I], the I-th block of that kind counted from 0
// ("cliffs.face.constraint[1].amplitude", "cliffs.curve[0].constraint[0].roughness"). Nothing when
// the file has no such block.
struct KeyTarget {
    const ast::Block* block;
    std::string key;
};
std::optional<KeyTarget> findKeyTarget(const ast::File& file, std::string_view name);

// `text` (which parsed to `file`) with each key of `overrides` (named as findKeyTarget reads them)
// written as its value in its block, or added to the block when the file leaves it out. Names of
// blocks the file does not have change nothing; featureOverrideErrors finds those of features.
std::string overrideFeatureKeys(const std::string& text, const ast::File& file, const std::map<std::string, double>& overrides);

// One message per name of `overrides` that is not "feature.key" of a feature `file` declares.
std::string featureOverrideErrors(const ast::File& file, const std::map<std::string, double>& overrides);

} // namespace voxc

#pragma once
// Feature keys set from outside the file, as `voxc view`'s sliders and libvoxc's overrides set
// them: the key's written value is replaced in the text given to the checker (or the key is added
// to the block when the file leaves it to its default), so the checker reads and checks it exactly
// as if the file said so; the file on disk is never written. Constants need no rewriting
// (CheckOptions::constOverrides).
#include "voxc/syntax/Ast.h"

#include <map>
#include <string>
#include <string_view>

namespace voxc {

// The key's assignment in `block`, or null when the block does not write it.
const ast::Assignment* findAssignment(const ast::Block& block, std::string_view key);

// `text` (which parsed to `file`) with each "feature.key" of `overrides` written as its value in
// the feature block of that name; likewise "grammar.key" and "grammar.rule.key" in grammar and
// rule blocks (the viewer's grammar sliders). Names of blocks the file does not have change
// nothing; featureOverrideErrors finds those of features.
std::string overrideFeatureKeys(const std::string& text, const ast::File& file, const std::map<std::string, double>& overrides);

// One message per name of `overrides` that is not "feature.key" of a feature `file` declares.
std::string featureOverrideErrors(const ast::File& file, const std::map<std::string, double>& overrides);

} // namespace voxc

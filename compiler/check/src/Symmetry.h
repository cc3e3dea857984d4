#pragma once
// `symmetry = ...` on a rule or a grammar: the rule is expanded into its rotated and reflected
// variants, each an ordinary rule of the grammar (so the interpreter, the kernels and every
// analysis see nothing new). An element is a signed permutation of the axes acting on a
// window's cells about the window's centre; the window's extent is permuted with it.
#include "Context.h"
#include "Sections.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace voxc::check {

// Variant axis i reads original axis `from[i]`, negated when `negate[i]`.
struct SymmetryElement {
    std::array<int, 3> from{0, 1, 2};
    std::array<bool, 3> negate{false, false, false};

    bool isIdentity() const;
    // "rot90y", "mirror_x", "rot90y_mirror_y", ...; outside the y-axis square group with y
    // flips, the signed permutation itself: "[z,-x,y]" (variant x = original z, ...).
    std::string name() const;
};

// The elements of a named group, identity first: none (1), x (2: mirror_x), z (2), xz (4),
// xyz (8: every axis reflection), rot_y (4: quarter turns about y), square (8: rot_y and the
// vertical mirrors), all (48: every rotation and reflection of the cube).
std::optional<std::vector<SymmetryElement>> symmetryGroup(std::string_view name);

// `symmetry = square;` or `symmetry = [rot90y, mirror_x];` (identity implied). Reports unknown
// names (E0010, with a suggestion) and returns nothing.
std::optional<std::vector<SymmetryElement>> readSymmetry(Context& context, const ast::Assignment& a);

// The rule under `element`: cells moved, extent permuted, name "rule@element".
CheckedRule applySymmetry(const CheckedRule& rule, const SymmetryElement& element);

// The rule followed by its distinct variants under `elements` (identity first), in group
// order; a variant equal to an earlier one (a symmetric window) is dropped.
std::vector<CheckedRule> expandSymmetry(const CheckedRule& rule, const std::vector<SymmetryElement>& elements);

} // namespace voxc::check

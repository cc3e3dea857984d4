#pragma once
// A rule's `stamp` blocks (feature transforms, voxc::Stamp), labelled with the field to stamp:
//   stamp arch_span { mode = union; offset = [4, 0, 0]; reach = [2, 12, 2]; material = sandstone; }
// The block is read with its rule; the field name is resolved once the fields are checked.
#include "Context.h"
#include "Sections.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <optional>
#include <string>

namespace voxc::check {

// One `stamp` block of a rule whose window is `windowSize`; reports its errors and returns
// nothing then. `reachLoc` receives the place of its `reach` value.
std::optional<Stamp> checkStampBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                     const std::string& rule, SourceLoc& reachLoc);

// E0012 at a stamp's reach when the grown windows of one phase of its sweep would cover a voxel
// more than Limits::maxStampOverlap times (phase spacing along each axis: phaseCount * stride;
// no more than the phase's anchors along it).
void checkStampOverlap(Context& context, const Grammar& grammar, const std::vector<RuleSyntax>& rules);

// Points every stamp of `grammars` at its field in `fields` by name (E0002 with a suggestion for
// an unknown one; E0013 for a field that reads an lsystem's point set, which is carved in
// grid coordinates only).
void resolveStampFields(Context& context, std::vector<Grammar>& grammars, const std::vector<Field>& fields);

} // namespace voxc::check

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
// nothing then. `reachLoc` and `offsetLoc` receive the places of its `reach` and `offset`
// values (its name when it has no offset).
std::optional<Stamp> checkStampBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                     const std::string& rule, SourceLoc& reachLoc, SourceLoc& offsetLoc);

// E0012 at a stamp's reach when the grown windows of one phase of its sweep would cover a voxel
// more than Limits::maxStampOverlap times (phase spacing along each axis: phaseCount * stride;
// no more than the phase's anchors along it).
void checkStampOverlap(Context& context, const Grammar& grammar, const std::vector<RuleSyntax>& rules);

// Points every stamp of `grammars` (`syntax` parallel) at its field in `fields` by name (E0002
// with a suggestion for an unknown one). A field with a stamp form in `stampFields` (parallel to
// `fields`, shorter or empty where none has one: an lsystem_cave's carve measured from the
// stamp's frame) is stamped through a copy appended to `fields`, one per declared stamp and
// shared by its variants, its point set binned over the stamp's frame box (PointSet::binnedInFrame).
// Such a stamp's offset must be whole voxels (E0007), and its reach must hold the carve: E0012
// at the reach where the skeleton, with the brush's reach around it, passes the grown window.
void resolveStampFields(Context& context, std::vector<Grammar>& grammars, const std::vector<CheckedGrammar>& syntax,
                        std::vector<Field>& fields, const std::vector<std::optional<Field>>& stampFields);

} // namespace voxc::check

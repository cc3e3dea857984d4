#pragma once
// The `lsystem_cave` feature: an lsystem block's skeleton carved as a field (CheckLsystemCave.cpp).
#include "Context.h"

#include "voxc/check/Check.h"
#include "voxc/syntax/Ast.h"

#include <optional>
#include <vector>

namespace voxc::check {

struct CheckedLsystemCave {
    Field field;
    // The same carve measured from a stamp's frame (lsystem::CarveFrame::Stamp), its network
    // moved so the turtle starts at the frame's origin, for the stamps that name the feature
    // (CheckStamps.h bins a copy of its point set over each stamp's frame).
    Field stampField;
    std::optional<uint8_t> material;
};

// Reads the feature's keys (located errors), grows the named lsystem's skeleton and builds the
// carve field for `world` (its seed draws the noise; the lists are binned over its grid) and
// the field stamps read.
std::optional<CheckedLsystemCave> checkLsystemCave(Context& context, const ast::FeatureDecl& decl, const World& world,
                                                   const ast::File& file, const std::vector<CheckedLsystem>& lsystems);

} // namespace voxc::check

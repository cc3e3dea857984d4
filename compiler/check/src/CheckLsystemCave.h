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
    std::optional<uint8_t> material;
};

// Reads the feature's keys (located errors), grows the named lsystem's skeleton and builds the
// carve field for `world` (its seed draws the noise; the lists are binned over its grid).
std::optional<CheckedLsystemCave> checkLsystemCave(Context& context, const ast::FeatureDecl& decl, const World& world,
                                                   const ast::File& file, const std::vector<CheckedLsystem>& lsystems);

} // namespace voxc::check

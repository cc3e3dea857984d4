#pragma once
// The generator records, one file each; Generators.cpp lists them.
#include "voxc/generators/dey/Generators.h"

namespace voxc::dey {

// Placement keys every generator accepts (grid-local voxels and degrees).
inline constexpr GeneratorKey kTranslateKey{"translate", GeneratorKeyType::Vec3, -1e6, 1e6, 0, {0, 0, 0}};
inline constexpr GeneratorKey kRotateKey{"rotate", GeneratorKeyType::Vec3, -360, 360, 0, {0, 0, 0}};

const GeneratorInfo& archGenerator();
const GeneratorInfo& caveGenerator();
const GeneratorInfo& overhangGenerator();

} // namespace voxc::dey

#pragma once
#include "JsonReporter.h"

namespace voxc::bench {

// Registers codegen cases (lowering, GLSL, glslang, SPIR-V validation: `voxc compile` without the
// files) at the per-sweep size limit of 4096 rule window cells; record n = rules in the program:
// - compile_8cube_rules: grammars of 8 rules with [8,8,8] windows (the largest window), one
//   grammar (n = 8) and four (n = 32), so time per rule can be compared across program sizes;
// - compile_16cell_rules: one grammar of 256 rules (Limits::maxRulesPerSweep) with [4,2,2] windows.
void registerCompileCases(JsonReporter& reporter);

// stamp_symmetry_compile (n = 1, 48): the CPU seconds of a cold `voxc run` (every cache off, on
// lavapipe) of bench/grammars/stamp_symmetry.vox, an lsystem_cave stamp, under `symmetry = none`
// and `all`; one untimed run first, three timed. tests/cli/symmetry_compile_time.sh asserts the
// ratio with a generous bound.
void registerStampSymmetryCompile(JsonReporter& reporter);

} // namespace voxc::bench

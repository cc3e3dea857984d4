#pragma once
// Bounds on one generated kernel (docs/language.md, "Limits"): the field code a sweep's stamp
// kernel holds (Limits::maxKernelFieldNodes) and the loop iterations one invocation of a stamp or
// speleothem kernel may take (Limits::maxKernelLoopIterations), each a located E0012 with the
// number. Both kernels loop over what the program decides: a voxel's stamp pass folds every
// firing whose grown window holds it, each firing's stamps walking their carve's lists, and a
// speleothem column checks each voxel it grows against its keep_clear carve's lists.
#include "Context.h"
#include "Sections.h"

#include "voxc/program/Program.h"

#include <vector>

namespace voxc::check {

// `syntax` is parallel to program.grammars; the lists of every point set are binned.
void checkKernelBounds(Context& context, const Program& program, const std::vector<CheckedGrammar>& syntax);

// Loop iterations one invocation of the speleothem stage's grow kernel (speleothem_grow.glsl) may
// take in a grid `height` voxels high.
uint64_t speleothemLoopIterations(const SpeleothemStage& stage, int32_t height);

} // namespace voxc::check

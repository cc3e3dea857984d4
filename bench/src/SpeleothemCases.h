#pragma once
#include "voxc/program/Program.h"

namespace voxc::bench {

// speleothems/N: an N x 96 x N rock grid with three stacked air chambers (start boxes), then a
// hoodoo speleothem stage with the default spawn rule over the whole cluster range.
// speleothems_base/N is the same program without the stage, so the difference of the two
// records is the stage's cost (its air-mask prepass and grow pass).
Program speleothemProgram(int n, bool withStage);

} // namespace voxc::bench

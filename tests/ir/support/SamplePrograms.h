#pragma once
// Small checked-looking programs built in C++ for the IR and codegen tests.
#include "voxc/program/Program.h"

namespace voxc::test {

// Two grammars that exercise every pass and kernel feature:
// - "overhang" (clamp [0, 1]): three [3,3,1] rules (one can never match, two share
//   predicates and differ in priority, weight and probability) and a [1,2,1] rule;
// - "smooth" (stride [2,1,2], no clamp): a [2,1,2] rule written in two layers that matches
//   everywhere, and a [1,1,1] sweep whose only rule can never match.
// The world has a negative origin and chunk 8 so chunk addressing straddles chunks; the
// start block has a fill, a box and a heightfield.
Program sampleProgram();

} // namespace voxc::test

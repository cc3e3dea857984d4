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

namespace voxc::test {

// Every way a program reads or writes materials (rock 1, sand 2, moss 3), hand-built until the
// checker accepts the syntax: start shapes with materials; grammar "weather" with MAT/NMAT
// tests, `MAT m` writes alone and beside SET/ADD, and a [2,1,1] rule that spreads moss across
// tiles over its iterations; then field stages union/subtract/intersect/paint with a material
// (intersect writes `none`). Fields: "half" (x < 20 ? 0.8 : 0.2, constant per chunk away from
// x = 20), "ramp" (x * 0.04), "slope" (z * 0.05 + 0.3), "low" (y < 16 ? 0.9 : 0.1).
// `withSet`: the pipeline is start, intersect slope (dead: a set follows and it writes no
// material), set low material moss, weather, paint half material rock; otherwise start, union
// half material moss, weather, subtract ramp material sand, intersect slope material none,
// paint half material rock.
Program materialProgram(bool withSet = false);

} // namespace voxc::test

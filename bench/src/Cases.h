#pragma once
// The benchmark cases: an example grammar resized to n^3 and run for one iteration over the
// whole grid with stride 1 (the thesis's worst case, Dey Table 3.5).
#include "voxc/program/Program.h"

#include <string>
#include <vector>

namespace voxc::bench {

struct Case {
    std::string name;    // "overhang", "cave"
    std::string example; // path below the source tree
};

const std::vector<Case>& grammarCases();

// Loads the example and resizes it to n^3 with whole-grid bounds, stride 1 and one iteration.
Program loadCaseProgram(const Case& benchCase, int n);

} // namespace voxc::bench

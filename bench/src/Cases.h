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

// The generator cases: examples/arch.vox, cave.vox and cliff.vox (Dey's thesis defaults) on an
// n^3 grid; the features keep their default size and place, as in the thesis's timings.
const std::vector<Case>& featureCases();
// An example as written (its own size), e.g. "examples/caves.vox".
Program loadExampleProgram(const std::string& example);

Program loadFeatureProgram(const Case& benchCase, int n);

// Grammar power (issue 15), run as written at 128^3: a rule under `symmetry = square` (8
// variants) and the same 8 variants written out by hand (bench/grammars/expand.py), then the
// stamping examples arches_between_cliffs and sea_caves resized to 128^3.
const std::vector<Case>& symmetryCases();
const std::vector<Case>& stampCases();

// The "fbm5" case: a 5-octave Perlin fBm density over n^3 voxels (frequency 0.02 per voxel,
// lacunarity 2, gain 0.5, seed 0), written by a `set` field stage.
Program fbm5Program(int n);

// The same fBm computed by libnoise (noise::module::Perlin, standard quality) on every core,
// one z slab per thread; returns the n^3 values.
std::vector<float> libnoiseFbm5(int n);
std::string libnoiseDescription();
// What the interpreter runs on: grammars on one thread, field stages on every core.
std::string interpDescription();
// The host field stage's threads and widest SIMD (VOXC_SIMD lowers it).
std::string fieldHostDescription();

// CPU time of the whole process, every thread (lavapipe runs a dispatch on worker threads of its
// own): on a shared machine the load stretches wall times, much less the CPU a run takes.
double processCpuMs();

} // namespace voxc::bench

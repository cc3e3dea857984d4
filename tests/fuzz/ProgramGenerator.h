#pragma once
// Random valid .vox programs for the differential fuzzer (DiffFuzz.cpp): a small world, start
// shapes and materials, user functions, typed field expressions over the builtin registry, Dey's
// feature generators and tiny lsystem_cave networks, small grammars whose rules may stamp them,
// and a pipeline that uses them. Valid by construction as far as the registries describe the language
// (the checker still has the last word: a program it rejects is counted, not compared).
#include <cstdint>
#include <string>

namespace voxc::fuzz {

// SplitMix64: the same sequence on every platform and standard library, so a seed names a program.
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}
    uint64_t next();
    uint32_t below(uint32_t n);               // uniform in [0, n), n > 0
    int32_t range(int32_t lo, int32_t hi);    // uniform in [lo, hi]
    double real(double lo, double hi);
    bool chance(double p);

private:
    uint64_t state_;
};

// The program for `seed`; the same seed always gives the same text.
std::string generateProgram(uint64_t seed);

} // namespace voxc::fuzz

#pragma once
// Solves kept on disk by earlier runs (docs/curves.md, "Solves kept between runs"): a curves or
// terrain block's table, over its whole declared box, in the directory compiled kernels are kept in
// (codegen::compileCacheDirectory(), its solves/ subdirectory), so a re-run, a `voxc view` reload
// or a region of an unchanged block reads its table instead of solving it. Content-addressed like
// the kernels: an entry's name is the SHA-256 of every checked input of the block's solve (the
// curves' control and constraint points and options, the box, the noise seed; a terrain's map,
// splines, erosion settings and world), where the solve ran (host or device, whose curves
// displacement differs in the last bits) and which build of voxc made it, so a changed block is
// never found rather than invalidated. An entry holds its body's SHA-256; one that does not match
// (truncated, corrupted, edited) is ignored, solved again and rewritten. Entries are written to a
// temp file and renamed, so concurrent runs see whole entries or none.
#include "voxc/program/SolveTable.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace voxc::stages {

// What solveBlocks did since the process started, for `voxc run --timings` and tests.
struct SolveCacheCounts {
    uint64_t solved = 0;    // tables solved (no entry, or the cache is off)
    uint64_t hits = 0;      // tables read from the cache
    uint64_t corrupted = 0; // entries that failed their check, solved again (also in `solved`)
};
SolveCacheCounts solveCacheCounts();

// The entry name of `block`'s solve (64 hex digits); `onDevice`: a device ran its global passes.
std::string solveKey(const CurvesBlock& block, bool onDevice);

// The table kept under `key` in `directory`'s solves/, or nothing (no entry; `corrupted` says
// whether one was there but failed its check).
std::optional<SolveTable> readSolve(const std::filesystem::path& directory, const std::string& key, bool& corrupted);
// Whether `directory`'s solves/ has an entry under `key` (unread, so not yet checked): the viewer
// shows a coarse preview only of blocks a run would solve rather than read.
bool hasSolve(const std::filesystem::path& directory, const std::string& key);
// Keeps `table` (its channels and phase times are not kept); a directory that cannot be written
// costs the next run a solve, never this one.
void writeSolve(const std::filesystem::path& directory, const std::string& key, const SolveTable& table);

// solveBlocks' counting.
void countSolve(bool hit, bool corrupted);

} // namespace voxc::stages

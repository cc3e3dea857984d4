#pragma once
// The viewer's progressive preview (docs/viewer.md, "Progressive preview"): a curves or terrain
// block that a run would solve (not in the solve cache) and that is large is first shown coarse,
// solved on a coarser box (curves) or to a coarser finest level (terrain), while the full solve
// runs in the background; the full solve is stages::solveBlocks', so the refined world is the one
// a plain run makes.
#include "voxc/program/Program.h"

#include <cstdint>
#include <string>
#include <vector>

namespace voxc::viewer {

struct PreviewOptions {
    // A curves block of more cells than this is previewed on a box coarser by the least power of
    // two that brings it to at most this many cells; 0 turns previews off.
    uint64_t curvesCells = uint64_t(1) << 18;
    // A terrain whose finest level is finer than this is previewed with this finest level (level L
    // has 2^L x 2^L cells) and the erosion steps of its levels only.
    int32_t terrainLevel = 7;
};

// Whether some block of `program` would be previewed: unsolved, past the options' sizes, and not in
// the solve cache (whose entry a full run would read in less time than a preview takes).
bool needsPreview(const Program& program, const PreviewOptions& options);

// The solve-cache keys of the curves and terrain blocks a full solve of `program` solves or reads
// (those without a table), in order: two programs with the same keys get the same tables.
std::vector<std::string> solveKeys(const Program& program);

// `program` with every such block's table made coarse (a curves table upsampled to the block's
// box, a terrain's table and sampled map from its coarser levels) and every other block solved as
// stages::solveBlocks solves it. Throws what the solves throw.
Program previewProgram(const Program& program, const PreviewOptions& options);

} // namespace voxc::viewer

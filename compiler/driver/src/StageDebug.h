#pragma once
// What `voxc interp` and `voxc run` share for looking at one stage: --after STAGE (the outputs as
// they were after that pipeline stage: the program run is the pipeline cut there), --diff STAGE
// (the same, and what the stage changed compared with the pipeline cut just before it), and
// --slice AXIS=INDEX with --channel density|material.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace voxc::driver {

struct StageDebugOptions {
    std::string after;
    std::string diff;
    std::string slice;
    std::string channel = "density";
};

void addStageDebugFlags(CLI::App& command, StageDebugOptions& options);

struct SliceSpec {
    int axis = 1;
    int index = 0;
};

// "y=12" inside a grid of `size`; UserError otherwise.
SliceSpec parseSlice(const std::string& text, glm::ivec3 size);

// The pipeline stage --after or --diff names.
struct StageCut {
    size_t stage = 0;  // index into Program::pipeline
    bool diff = false; // --diff: also compare with the pipeline cut before the stage
    size_t stages = 0; // the whole pipeline's, for the heading
};

// The stage `options` names, if any: its position as listed ("2"), its label ("subtract tunnel")
// or the name of its grammar, field or block when one stage alone has it. UserError listing the
// pipeline's stages (with a "did you mean") for any other name.
std::optional<StageCut> selectStage(const Program& program, const StageDebugOptions& options);

// `program` with the stages after `last` left out: what runs for --after.
Program throughStage(Program program, size_t last);

// "stage 2 of 4 'subtract tunnel' (cave.vox:14:3)\n": the heading of --after and --diff output.
std::string describeCut(const Program& program, const StageCut& cut);

// The slice of --slice/--channel (empty without --slice), for `grid`.
std::string renderChosenSlice(const Program& program, const StageDebugOptions& options, const DenseGrid& grid,
                              float iso);

// --diff's report: what changed from `before` to `after` by kind and material, the box of the
// change, and a slice marking the changes (the --slice layer, else the y layer with the most).
std::string reportStageDiff(const Program& program, const StageDebugOptions& options, const DenseGrid& before,
                            const DenseGrid& after, float iso);

} // namespace voxc::driver

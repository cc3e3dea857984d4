#pragma once
// `--region MINX,MINY,MINZ:MAXX,MAXY,MAXZ` of `voxc run` and `voxc interp`: the program to run for
// that box of the world (the box grown by the pipeline's halo), and the crop back to the box.
#include "Common.h"

#include "voxc/stages/Region.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace voxc::driver {

struct RegionRun {
    Program program;                       // what to run: the region's grid, or the whole world
    std::optional<stages::GridBox> region; // the box asked for, in the declared grid's voxels
    stages::GridBox computed;              // the grid `program` runs: region + halo, clipped

    // The asked-for voxels of a grid computed from `program` (a ChunkedGrid's at the box's world place).
    DenseGrid crop(const DenseGrid& grid) const;
    ChunkedGrid crop(const ChunkedGrid& grid) const;
    // "region 10,0,-3:40,64,20 of the world: a 62x64x55 grid (halo 16, 0, 16)\n", or "" for a whole-world run.
    std::string describe() const;
};

// `voxc check --explain-halo`: per stage, its dependency radius and how it is made up, then the halo.
std::string explainHalo(const Program& program, const std::string& file);

void addRegionFlag(CLI::App& command, std::string& region);

// `overrides` with the box of `region` (empty: none) for the check, which then bounds the
// region's grid instead of the world's (CheckOptions::region).
WorldOverrides withRegion(WorldOverrides overrides, const std::string& region);

// `region` empty: the whole world. Otherwise UserError for a box that is not inside the world.
RegionRun planRegionRun(Program program, const std::string& region);

} // namespace voxc::driver

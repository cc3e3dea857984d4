#pragma once
// A world on disk, tile by tile (`voxc world`): the declared grid cut into cubes of `tile` voxels
// from its corner, each computed as a region (voxc/stages/Region.h: the tile plus the pipeline's
// halo, so its voxels are the whole world's there) and written as an OpenVDB file, then listed
// in DIR/index.json with its SHA-256. Memory holds one tile's grid at a time. A run that stops
// (killed, an error) resumes: a tile whose file is listed with its hash is kept, anything else
// is computed again; every file is written to a temp file and renamed.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace voxc::world {

struct TileProgress {
    int64_t done = 0;      // tiles finished, kept ones included
    int64_t total = 0;
    int64_t kept = 0;      // tiles a previous run wrote whose files still hash as listed
    double seconds = 0.0;  // since the run started
};

struct WorldOptions {
    std::string directory;
    int32_t tile = 256;
    std::string sourceText; // the .vox text: the index records its hash, so tiles of another file are not kept
    // Computes a region's grid from its program (the Vulkan executor, or the interpreter).
    std::function<DenseGrid(const Program& region)> run;
    // Called after every tile (progress on a terminal; tests stop a run here by throwing).
    std::function<void(const TileProgress&)> progress;
};

struct WorldSummary {
    int64_t tiles = 0, kept = 0;
    uint64_t voxelsComputed = 0; // over every computed tile's grid (its halo included)
    uint64_t voxelsWritten = 0;  // the tiles' own voxels, kept ones included
    uint64_t voxelsKept = 0;     // the kept tiles' voxels
};

// Who computes the tiles that are not up to date: the calling process in tile order (the
// default), or other processes (MpiTiles.h). `compute(t)` computes and writes tile t of the
// world's tile list and returns its file's SHA-256; `done(t, sha256)` must then be called here,
// in the calling process, once per tile, in any order.
using ComputeTile = std::function<std::string(int64_t tile)>;
using TileDone = std::function<void(int64_t tile, const std::string& sha256)>;
using TileScheduler =
    std::function<void(const std::vector<int64_t>& pending, const ComputeTile& compute, const TileDone& done)>;

// `program` is the whole world's (World::localBase 0). UserError when the directory holds
// another world's index or is not a directory. The index lists the finished tiles in tile order,
// so it ends the same bytes whatever order they finished in.
WorldSummary writeWorld(const Program& program, const WorldOptions& options, const TileScheduler& scheduler = {});

// Computes tile `index` (x fastest, then y, then z) and writes its file atomically; returns its
// SHA-256. What `writeWorld` runs for each pending tile, and what another process runs for it.
std::string writeTile(const Program& program, const WorldOptions& options, int64_t index);

// The file name of tile (i, j, k) inside the directory.
std::string tileFileName(glm::ivec3 tile);

} // namespace voxc::world

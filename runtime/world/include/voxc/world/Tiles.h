#pragma once
// A world on disk, tile by tile (`voxc world`): the declared grid cut into cubes of `tile` voxels
// from its corner, each computed as a region (voxc/stages/Region.h: the tile plus the pipeline's
// halo, so its voxels are the whole world's there) and written as an OpenVDB file, with its share
// of the world's marching-cubes mesh beside it, then listed in DIR/index.json with their SHA-256.
// Memory holds one tile's grid at a time. A run that stops (killed, an error) resumes: a tile
// whose files are listed with their hashes is kept, anything else is computed again; every file
// is written to a temp file and renamed.
//
// A tile's mesh is made by the cells whose minimum corner lies in the tile (on the world's low
// faces also the outside cells before it), computed from the tile's voxels, one more on its high
// sides (the cells' far corners) and one more on every side (the corners' gradients), all of them
// the world's voxels. So two tiles compute each vertex on their common face from the same samples
// with the world's crossing margin: the same bits, and the tiles' meshes welded by position are
// the whole world's mesh (closed and manifold). A tile without triangles has no mesh file.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"
#include "voxc/stages/Region.h"

#include <cstdint>
#include <functional>
#include <optional>
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
    // Only the tiles that meet this box of the declared grid (grid-local voxels), whole; else every
    // tile. Needed for a world unbounded in x or z. The index keeps listing an earlier run's tiles
    // outside it, so a world can be written box by box into one directory.
    std::optional<stages::GridBox> region;
    std::string sourceText; // the .vox text: the index records its hash, so tiles of another file are not kept
    std::string meshFormat = "glb"; // each tile's mesh: "glb", "ply", or "" for none
    float iso = 0.5f;               // the meshes' surface level
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

// The SHA-256 of a tile's files; `mesh` empty when it has no mesh file.
struct TileDigests {
    std::string voxels, mesh;
};

// Who computes the tiles that are not up to date: the calling process in tile order (the
// default), or other processes (MpiTiles.h). `compute(t)` computes and writes tile t of the
// world's tile list and returns its files' digests; `done(t, digests)` must then be called here,
// in the calling process, once per tile, in any order.
using ComputeTile = std::function<TileDigests(int64_t tile)>;
using TileDone = std::function<void(int64_t tile, const TileDigests& digests)>;
using TileScheduler =
    std::function<void(const std::vector<int64_t>& pending, const ComputeTile& compute, const TileDone& done)>;

// `program` is the whole world's (World::localBase 0). UserError when the directory holds
// another world's index or is not a directory. The index lists the finished tiles in tile order,
// so it ends the same bytes whatever order they finished in.
WorldSummary writeWorld(const Program& program, const WorldOptions& options, const TileScheduler& scheduler = {});

// Computes tile `index` of the run's tiles (x fastest, then y, then z) and writes its files atomically; returns their
// digests. What `writeWorld` runs for each pending tile, and what another process runs for it.
TileDigests writeTile(const Program& program, const WorldOptions& options, int64_t index);

// The file names of tile (i, j, k) inside the directory: its voxels, and its mesh in `format`.
std::string tileFileName(glm::ivec3 tile);
std::string tileMeshFileName(glm::ivec3 tile, const std::string& format);

} // namespace voxc::world

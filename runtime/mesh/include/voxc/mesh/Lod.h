#pragma once
// Level of detail for marching cubes: chunks meshed at different levels that join with no cracks
// and no T-junctions.
//
// - Data by decimation (LodPyramid): level k's sample at world lattice point i is LOD0's sample at
//   world position 2^k i, bit for bit. Point decimation, not a minimum or an average, because a
//   coarse chunk and its finer neighbour must see the same value where their samples coincide (the
//   transition cells below read both); an average would also move the iso surface.
// - A chunk at level k has cells 2^k voxels wide, so a chunk holds chunkSize / 2^k cells per axis
//   (level 2^k <= chunkSize). Touching chunks (faces, edges and corners) differ by at most one
//   level (the 2:1 rule, checkLodLayout); balanceLod refines a layout until it holds.
// - Where a chunk at level k+1 touches a chunk at level k, its cells there become transition cells
//   (voxc/mesh/TransitionCells.h): the cell's edges and faces on the shared boundary take the finer
//   level's samples, so both chunks cut the boundary the same way, through the same vertices.
// - Vertex identity is the crossed lattice edge: its lower world corner, axis and level; vertices
//   are ordered by it and triangles by their cell's minimum corner, so the mesh is the same for
//   every thread order, and a layout of only level 0 gives meshMarchingCubes' mesh byte for byte.
//   Positions and normals follow MarchingCubes.h with the edge's length 2^k in place of 1 (the
//   crossing margin is the same fraction of the edge; the normal's central differences span 2^k).
//   At levels >= 1 a vertex on an edge leaving the grid is clamped along its edge to the world's box
//   [origin - 1/2, origin + size - 1/2], where level 0's border walls lie, so coarse walls never stand
//   outside it (unclamped they would by up to 2^k - 1/2 voxels).
// - Ramp width: linear interpolation on a level-k edge is exact for a plane only when both samples
//   lie on the density ramp, i.e. a ramp of width w >= 2^(k+1) (density(sdf, w)); with w = 1 the
//   coarse samples are almost all clamped to 0 or 1 and coarse vertices fall near edge midpoints.
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Mesh.h"
#include "voxc/mesh/SurfaceNets.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace voxc {

inline constexpr int kMaxLodLevel = 6;

// Decimated levels of a grid. Holds a reference to `lod0`, which must outlive it; after an edit of
// lod0, refresh() brings every level up to date over the decimated box of the edit.
class LodPyramid {
public:
    LodPyramid(const ChunkedGrid& lod0, int maxLevel);
    int maxLevel() const { return int(levels_.size()); }
    const ChunkedGrid& lod0() const { return *lod0_; }
    // Level k's grid: its layout's origin and size count level-k lattice points (world position
    // 2^k i); nullopt when no lattice point of level k falls inside the grid. k >= 1.
    const std::optional<ChunkedGrid>& level(int k) const { return levels_[size_t(k - 1)]; }
    // The sample at world lattice point i of `level`: 0 (air, material none) outside the grid and
    // for densities that are not finite, as the meshers read them.
    float at(int level, glm::ivec3 lattice) const;
    uint8_t materialAt(int level, glm::ivec3 lattice) const;
    // Re-decimates LOD0's grid-local voxels [first, last] (inclusive) into every level.
    void refresh(glm::ivec3 first, glm::ivec3 last);

private:
    const ChunkedGrid* lod0_;
    std::vector<std::optional<ChunkedGrid>> levels_; // levels 1..maxLevel
};

// A level for every world chunk holding cells of the grid (the chunks of cellChunks: from the one
// holding gridOrigin - 1 to the one holding the last voxel).
struct LodLayout {
    glm::ivec3 firstChunk{0};
    glm::ivec3 chunkCount{0};
    int32_t chunkSize = 32;
    std::vector<uint8_t> levels; // x fastest

    static LodLayout uniform(const ChunkLayout& grid, int level);
    // Levels growing with the distance d from `point` (world voxels) to each chunk's box, like
    // rings of a clipmap: level = floor(log2(1 + d / chunkSize)), at most maxLevel, then balanced.
    static LodLayout aroundPoint(const ChunkLayout& grid, glm::vec3 point, int maxLevel);

    bool contains(glm::ivec3 chunk) const;
    int levelAt(glm::ivec3 chunk) const { return levels[index(chunk)]; }
    void setLevel(glm::ivec3 chunk, int level) { levels[index(chunk)] = uint8_t(level); }
    int maxLevel() const;

private:
    size_t index(glm::ivec3 chunk) const;
};

// Lowers levels until no two touching chunks are two or more levels apart (a chunk next to a
// finer one drops to one above it, repeated until nothing changes).
void balanceLod(LodLayout& layout);
// UserError when two touching chunks are two or more levels apart (naming both), or when a level's
// cells are wider than a chunk.
void checkLodLayout(const LodLayout& layout);

struct LodStats {
    size_t chunks = 0;
    size_t skippedChunks = 0; // all samples on one side of iso
    std::array<size_t, kMaxLodLevel + 1> chunksPerLevel{};
    size_t transitionFaces = 0; // chunk faces whose neighbour across is one level finer
    size_t transitionCells = 0; // cells with samples of the finer level (faces, edges), meshed or not
};

// Meshes every chunk of `layout` at its level from `pyramid` (whose maxLevel must reach the
// layout's), with transition cells against finer neighbours, and keeps each chunk's share; mesh()
// welds them into one mesh, closed and manifold. The layout must cover the pyramid's grid
// (LodLayout::uniform / aroundPoint) and pass checkLodLayout (UserError otherwise). The mesher
// refers to the pyramid, which must outlive it.
class LodMesher {
public:
    LodMesher(const LodPyramid& pyramid, const LodLayout& layout, const MeshOptions& options);
    ~LodMesher();
    // After LOD0's grid-local voxels [first, last] changed and pyramid.refresh(first, last):
    // re-meshes every chunk that reads a sample in that box (its cells' corners, and one step
    // beyond for the normals), at every level, and returns those chunks. mesh() then equals a
    // mesher built afresh.
    std::vector<glm::ivec3> update(glm::ivec3 first, glm::ivec3 last);
    Mesh mesh() const &;
    Mesh mesh() &&; // without copying the chunks' shares first
    const LodStats& stats() const; // as of construction

private:
    struct State;
    std::unique_ptr<State> state_;
};

// LodMesher(pyramid, layout, options).mesh(), with its stats.
Mesh meshLod(const LodPyramid& pyramid, const LodLayout& layout, const MeshOptions& options, LodStats* stats = nullptr);

} // namespace voxc

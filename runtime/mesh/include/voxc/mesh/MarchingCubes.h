#pragma once
// Marching cubes with a case table derived in code (McTable.cpp) so that every mesh is closed,
// manifold and consistently oriented.
//
// Conventions (the same as surface nets, voxc/mesh/SurfaceNets.h): a voxel is solid when its
// density is > iso; voxels outside the grid, and densities that are not finite, read as 0; voxel
// (x,y,z) sits at gridOrigin + (x,y,z); triangles wind counter-clockwise seen from air; normals
// are the negated field gradient (central differences at the edge's two samples, blended with
// the crossing), or, where that vanishes, the edge direction from its solid to its air sample.
//
// - Vertex identity is the crossed grid edge: one vertex per edge, at
//   p0 + t along the edge, t = (iso - d0) / (d1 - d0) from the edge's lower corner p0 (in double,
//   then float), kept a margin (crossingMargin) away from both corners so that samples exactly at
//   iso cannot put two vertices at one point and collapse a triangle.
// - Vertices are ordered by global edge, triangles by global cell then table order, so the mesh
//   is bit-identical for every chunk size and thread order.
// - Materials: a vertex takes the material of its edge's solid voxel (as a surface-nets quad
//   does); a triangle takes the most common material among its cell's solid corners, ties to
//   the lowest id (as a surface-nets vertex does).
#include "voxc/mesh/SurfaceNets.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace voxc {

// The least margin, 2^-10 voxel: invisible (an integer plane at iso moves by this much) and 16
// float spacings wide for world coordinates below 2^10.
inline constexpr float kCrossingMargin = 1.0f / 1024.0f;

// The whole grid on the chunk workers. The samples are classified into solid/air bits in one
// streaming pass (AVX2 where the CPU has it); cells are then tested 64 at a time on those bits, and
// only the cells the surface crosses, and their crossed edges, read densities and materials. The
// result equals marching_cubes::mergeChunks over every chunk's extractChunk, byte for byte.
Mesh meshMarchingCubes(const ChunkedGrid& grid, const MeshOptions& options, MeshStats* stats = nullptr);
// "avx2" or "scalar": the sample classification the host meshers run on this CPU.
const char* hostMeshSimd();

// Cells named by their minimum corner, grid-local, begin <= cell < end; the grid's cells run from
// -1 to its size - 1 (the air outside closes the surface).
struct CellBox {
    glm::ivec3 begin, end;
};
// The part of a mesh that the cells `cells` make, with `margin` in place of the grid's own
// crossingMargin: a tile of a world cut into tiles, from a grid holding the tile's cells' corners
// and their neighbours for the gradients (voxc/world/Tiles.h). Two tiles meshed with the world's
// margin compute each vertex on their common face from the same samples, so they carry the same
// bits, and the tiles' meshes welded by position are the world's mesh.
Mesh meshMarchingCubesCells(const ChunkedGrid& grid, const CellBox& cells, float margin, const MeshOptions& options,
                            MeshStats* stats = nullptr);

namespace marching_cubes {

// Corner c of a cell is at offset (c&1, (c>>1)&1, (c>>2)&1); case bit c is set when corner c is
// solid. Edge e runs along axis e/4 from its lower corner edgeCorners(e)[0] to [1].
inline glm::ivec3 cornerOffset(int corner) { return {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1}; }
std::array<int, 2> edgeCorners(int edge);
inline int edgeAxis(int edge) { return edge / 4; }

// The most common of a cell's `count` solid-corner material ids; ties go to the lowest id, and no
// solid corner gives 0 (kMaterialNone). The host and the device mesher both vote with it.
inline uint8_t mostCommonMaterial(const uint8_t* ids, int count) {
    // Most cells lie inside one material: then it is the answer, without the vote.
    if (count > 0 && std::count(ids, ids + count, ids[0]) == count) return ids[0];
    uint8_t best = 0;
    int bestVotes = 0;
    for (int i = 0; i < count; ++i) {
        const int votes = int(std::count(ids, ids + count, ids[i]));
        if (votes > bestVotes || (votes == bestVotes && ids[i] < best)) {
            best = ids[i];
            bestVotes = votes;
        }
    }
    return best;
}

inline constexpr int kMaxTrianglesPerCell = 12;

// Triangles of one case as cell edges, three per triangle, counter-clockwise seen from air.
struct CellCase {
    uint8_t triangleCount = 0;
    std::array<uint8_t, kMaxTrianglesPerCell * 3> edges{};
};
// The 256 cases. Derived from one rule per cell face, so the two cells that share a face always
// cut it the same way: a face whose solid corners are diagonal (ambiguous) keeps them apart.
const std::array<CellCase, 256>& caseTable();

// The grid's margin: 16 float spacings of its largest world coordinate, at least kCrossingMargin
// and at most 1/8 voxel. Up to 2^17 it keeps every triangle's area above zero in float; beyond,
// positions are too coarse for any margin, and zero-area triangles are possible (and reported).
float crossingMargin(const ChunkLayout& layout);

// The crossing of an edge as a fraction of its length from the lower sample d0 towards d1, at
// least `margin` from either end.
float crossing(float d0, float d1, float iso, float margin = kCrossingMargin);

// One chunk's share of the mesh, keyed by global grid edge and cell (exposed for the seam tests):
// the vertices of every crossed edge its cells use, including those on its high faces that the
// next chunk also produces, and the triangles of its cells in cell order.
struct EdgeVertex {
    uint64_t edge; // owner key * 3 + axis; the owner is the edge's lower corner, keyed like a cell
    glm::vec3 position;
    glm::vec3 normal;
    uint8_t material;
};
struct CellTriangle {
    uint64_t cell;
    std::array<uint64_t, 3> edges;
    uint8_t material;
};
struct ChunkMesh {
    std::vector<EdgeVertex> vertices;   // ascending edge
    std::vector<CellTriangle> triangles; // ascending cell, table order within a cell
};
ChunkMesh extractChunk(const ChunkedGrid& grid, float iso, glm::ivec3 worldChunk);
// Joins chunk meshes into one: vertices in ascending edge key (a key from two chunks must carry
// the same bits, else InternalError), triangles in ascending cell key, chunk order within a cell.
Mesh mergeChunks(std::vector<ChunkMesh> parts);

} // namespace marching_cubes
} // namespace voxc

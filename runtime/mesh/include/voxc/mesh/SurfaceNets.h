#pragma once
// Naive surface nets (Gibson 1998, centre-of-mass variant as in Dey ch. 3): one vertex per cell
// that the surface crosses, at the mean of the crossings on the cell's 12 edges, and one quad
// per crossed grid edge joining the vertices of the four cells around it.
//
// Conventions:
// - A voxel is solid when its density is > iso, air when <= iso.
// - Voxels outside the grid read as density 0, so for iso >= 0 the mesh of a bounded grid is
//   closed: the surface wraps the grid boundary half a voxel outside it (at iso 0.5 and density 1).
// - Voxel (x,y,z) sits at world position gridOrigin + (x,y,z); vertices are in world coordinates.
// - For iso >= 0 the mesh is always closed, but not always manifold: a cell face whose corners alternate
//   solid/air (a saddle of the field) joins two vertices by four quads, a non-manifold edge.
//   Naive surface nets does not resolve that ambiguity; smooth convex shapes never hit it.
// - Triangles wind counter-clockwise seen from air. Normals are the negated field gradient
//   (central differences at the cell's corners, blended trilinearly at the vertex), so they point
//   from solid to air; where that gradient vanishes the adjacent faces' normals stand in.
// - Work is split into the layout's world-aligned chunks (a cell belongs to the chunk holding
//   its minimum corner), but vertices and triangles are ordered by global cell, so the mesh is
//   identical, bit for bit, for every chunk size.
// - Materials (Mesh::vertexMaterials / triangleMaterials) are always filled, all 0 when the grid
//   has none; only solid voxels' materials are read.
// - A chunk whose cells read only solid or only air voxels (its own voxels plus the one-voxel
//   apron into the next chunks) has no surface, so it is skipped before its samples are gathered.
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Mesh.h"

#include <cstddef>

namespace voxc {

struct MeshOptions {
    float iso = 0.5f;
    bool skipUniformChunks = true; // off only to test that skipping never changes the mesh
};

struct MeshStats {
    size_t chunks = 0;        // world chunks holding cells
    size_t skippedChunks = 0; // of those, skipped because all their cells are on one side of iso
    // Marching cubes only: world-aligned 8^3 tiles of cells, those holding a cell the surface
    // crosses (the only tiles whose densities it reads past the one classifying pass), and the
    // cells whose case it looked up (on the host the crossed ones, on the device every cell of
    // the crossed tiles; every cell without skipping).
    size_t tiles = 0;
    size_t activeTiles = 0;
    size_t cellsVisited = 0;
    // Host marching cubes only: the densities its classifying pass read. With the grid's tile
    // ranges (ChunkedGrid::tileRanges) only the tiles that straddle iso are read; without them,
    // or without skipping, every sample.
    size_t samplesRead = 0;
    // Host marching cubes only: the wall time, within the call, of orienting the vertex normals
    // to their triangles (orientNormalsToFaces), which `voxc run --timings` shows as `normals`.
    double normalsMs = 0.0;
};

Mesh meshSurfaceNets(const ChunkedGrid& grid, const MeshOptions& options, MeshStats* stats = nullptr);
Mesh meshSurfaceNets(const ChunkedGrid& grid, float iso = 0.5f);

} // namespace voxc

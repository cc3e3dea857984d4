#pragma once
// Transition cells: the triangles of a cell some of whose edges and faces carry samples of the
// next finer level, so that a chunk meshed at LOD k+1 joins a neighbour at LOD k (voxc/mesh/Lod.h).
//
// A cell is a cube of two half-steps per axis; its possible samples are the 27 points of that
// 3x3x3 half-step lattice, point (x,y,z) with x,y,z in {0,1,2} numbered x + 3y + 9z. A regular cell
// has only its 8 corners. A cell edge is *split* when its midpoint is a sample, a face is *refined*
// when its centre is (then its four edge midpoints are samples too): a refined face is four fine
// cell faces, exactly what the finer neighbour's cells see there. The usual transition cell (a
// coarse cell against a finer chunk across one face) has 13 samples: its 9-sample full-resolution
// face and the 4 corners of its opposite, half-resolution face (Transvoxel's count; there the
// half-resolution face is a thin copy of the full one moved inwards, here it is the cell's own far
// face, so no vertex has to move to make room and the export needs no vertex shader).
//
// The triangles are derived, never typed in, by the rule the regular table (McTable.cpp) uses:
// each facet of the cell's surface (a fine square of a refined face, or a face as a polygon through
// its corners and the midpoints of its split edges) is cut on its own, each run of solid samples
// along its boundary cut off by one segment between the two crossings around it. A facet is shared
// by the two cells on either side, which see the same samples and apply the same rule, so their
// cuts agree; on a plain square the rule is the regular table's. Segments are chained into loops
// through the crossed sub-edges (each lies on exactly two facets) and every loop is triangulated
// without a chord that another cell can draw too, so no edge is used by more than two triangles:
// none between two vertices on one facet (the cell across it), on one cube edge line (the cells
// around it; a coarse one holds the whole line), or in one face that is not refined (the coarse
// cell across it); across a refined face the other cells are fine and each holds one of its
// squares. On a regular cell this is the regular table's rule (no chord within a face). Nor is a
// triangle flat where binary samples put the vertices (the sub-edges' midpoints). A loop that
// allows no such triangulation is fanned from a vertex of its own inside the cell, which keeps
// both promises (16 of the 8,192 one-face cases, 126 of 131,072 two-face and 384 of 1,048,576
// three-face cases; none on LodTest's sphere, 18 of 15,512 transition cells on noise).
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace voxc::transition_cells {

inline constexpr int kPoints = 27;
inline glm::ivec3 pointOffset(int point) { return {point % 3, (point / 3) % 3, point / 9}; } // in half-steps
inline int pointAt(glm::ivec3 p) { return p.x + 3 * p.y + 9 * p.z; }
// The 8 corners of a regular cell, as a 27-bit point mask.
inline constexpr uint32_t kCornerPoints = 1u << 0 | 1u << 2 | 1u << 6 | 1u << 8 | 1u << 18 | 1u << 20 | 1u << 24 | 1u << 26;

// A sub-edge of the cell: from lattice point `lower` one or two half-steps along `axis` (one for
// the halves of a split edge and the edges inside a refined face, two for an edge not split).
struct SubEdge {
    uint8_t lower;
    uint8_t axis;
    uint8_t halfSteps;
    bool operator==(const SubEdge&) const = default;
};

// A triangle corner: the vertex on a crossed sub-edge, or the centre of loop `loop` (a point
// strictly inside the cell, near the mean of the loop's vertices), which only that loop's fan uses.
struct CellVertex {
    SubEdge edge{};
    int8_t loop = -1; // >= 0: the centre of centredLoops[loop]
};

// Triangles, three corners each, counter-clockwise seen from air. A loop that has no triangulation
// under the rules below is fanned around its centre instead.
struct CellTriangles {
    std::vector<CellVertex> corners;
    std::vector<std::vector<SubEdge>> centredLoops;
    size_t triangleCount() const { return corners.size() / 3; }
};

// True when `points` is a shape this derivation handles: the 8 corners, edge midpoints, and face
// centres whose four edge midpoints are present; never the cell's centre.
bool validShape(uint32_t points);

// The triangles of the cell with samples `points` (validShape) of which `solid` (a subset) are solid.
CellTriangles deriveCell(uint32_t points, uint32_t solid);

} // namespace voxc::transition_cells

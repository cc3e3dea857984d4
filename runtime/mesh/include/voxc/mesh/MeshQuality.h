#pragma once
// A mesh checker independent of the meshers and of analyzeTopology (its own edge map, its own
// predicates): what `voxc run` reports for the mesh it wrote, and what the mesh tests assert.
// It accepts any Mesh, including broken ones (indices out of range, NaN positions).
#include "voxc/mesh/Mesh.h"

#include <cstddef>
#include <string>

namespace voxc {

struct MeshQuality {
    size_t vertices = 0;
    size_t triangles = 0;
    size_t boundaryEdges = 0;      // undirected edges of exactly one triangle (holes)
    size_t nonManifoldEdges = 0;   // undirected edges of three or more triangles
    size_t misorientedEdges = 0;   // edges of two triangles that both run them the same way
    size_t zeroAreaTriangles = 0;  // three distinct vertices whose float cross product is exactly 0
    size_t repeatedIndexTriangles = 0; // a vertex index used twice in one triangle
    size_t badIndexTriangles = 0;  // an index >= the vertex count (left out of every other count)
    size_t nonFiniteVertices = 0;  // a position or normal component that is NaN or infinite
    double signedVolume = 0.0;     // divergence theorem, in double; > 0 when triangles face out

    // Closed, every edge shared by exactly two triangles running it in opposite directions.
    bool manifold() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 && badIndexTriangles == 0; }
};

MeshQuality measureMeshQuality(const Mesh& mesh);

// "V vertices, T triangles, B boundary edges, N non-manifold edges, Z zero-area triangles"
// (plus the other counts, only when not zero).
std::string describeMeshQuality(const MeshQuality& quality);

} // namespace voxc

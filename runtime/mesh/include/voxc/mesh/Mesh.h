#pragma once
// An indexed triangle mesh in world voxel coordinates, and checks of its topology.
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/ext/vector_double3.hpp>
#include <vector>

namespace voxc {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // unit length, one per position, pointing from solid to air
    std::vector<uint32_t> triangles;  // three indices per triangle, counter-clockwise seen from outside
    // Material ids (voxc::Material; 0 = none), read from solid voxels by the mesher's rules
    // (MarchingCubes.h; surface nets: docs/architecture.md). Same length as positions / triangles.size() / 3.
    std::vector<uint8_t> vertexMaterials;
    std::vector<uint8_t> triangleMaterials;
    // The last normalSplits.size() vertices are copies orientNormalsToFaces made of vertices whose
    // triangles face too many ways for one normal: copy i is a second normal at the point of
    // vertex normalSplits[i], so the topology (analyzeTopology) counts it as that vertex.
    std::vector<uint32_t> normalSplits;
};

struct MeshTopology {
    size_t boundaryEdges = 0;        // undirected edges used by one triangle
    size_t nonManifoldEdges = 0;     // undirected edges used by three or more triangles
    size_t degenerateTriangles = 0;  // a repeated index or zero area
    size_t duplicateTriangles = 0;   // triangles over the same three vertices as an earlier one
    size_t misorientedEdges = 0;     // two-triangle edges traversed in the same direction by both

    // No edge is used by only one triangle: the surface has no holes.
    bool closed() const { return boundaryEdges == 0; }
    // Every undirected edge is used by exactly two triangles.
    bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
};

MeshTopology analyzeTopology(const Mesh& mesh);

// A triangle's geometric normal: the cross product of its edges b - a and c - a (counter-clockwise
// seen from its front), in double from the float positions; zero for a triangle without area.
glm::dvec3 triangleNormal(const Mesh& mesh, size_t triangle);

// The normals a renderer shades with must face the side each triangle's winding shows, or a
// triangle is lit from behind. A field's gradient (the meshers' normals) points the wrong way
// where a feature is thinner than its central differences, so every vertex whose normal is
// zero, or more than 90 degrees from the geometric normal of any triangle using it, takes
// instead the sum of those triangles' unit normals, or where that is not within 90 degrees of
// each, the direction whose largest angle to them is least. Where no direction is within 90
// degrees of all (a thin sheet or ridge folds the triangles around a point back on themselves),
// the triangles are split into groups, in triangle order, each joining the first group it can
// share a normal with; the first keeps the vertex and each other group gets a copy at the same
// position (appended, listed in Mesh::normalSplits) with its own normal. Positions are
// untouched; the result depends only on the mesh, so a mesh that is the same for every chunking
// keeps the same bits. Returns the number of vertices whose normal changed or that were split.
size_t orientNormalsToFaces(Mesh& mesh);

// orientNormalsToFaces' second step, for a mesher that finds the vertices to re-derive itself:
// `against` has a byte per vertex, 1 where its normal is zero or faces away from one of its
// triangles (glm::dot(glm::dvec3(normal), triangleNormal) < 0 for a triangle of nonzero
// triangleNormal), else 0; the triangles of such a vertex v, in triangle order (once per corner
// that is v), are triangles[incident[v]] to triangles[incident[v + 1] - 1] (incident: one more
// entry than vertices). orientNormalsToFaces(mesh) is this step after finding them by a pass
// over every triangle; the result is the same.
size_t orientFlaggedNormals(Mesh& mesh, const std::vector<uint8_t>& against, const std::vector<uint32_t>& incident,
                            const std::vector<uint32_t>& triangles);

} // namespace voxc

#pragma once
// An indexed triangle mesh in world voxel coordinates, and checks of its topology.
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
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

} // namespace voxc

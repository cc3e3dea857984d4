#pragma once
// Triangle meshes from glTF 2.0 (.glb, or .gltf with its buffers embedded as data: URIs; read by
// tinygltf, every node of the default scene with its transform), Wavefront OBJ (`v` and `f`
// records; polygons split into fans) and PLY (ascii and binary little/big endian; the vertex
// element's x, y, z and the face element's index list).
#include "voxc/generators/inputs/Inputs.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string_view>
#include <vector>

namespace voxc::inputs {

struct TriangleMesh {
    std::vector<glm::dvec3> points;
    std::vector<glm::uvec3> triangles; // indices into points
};

enum class MeshFormat { Gltf, Obj, Ply };

// The format a file name's extension says (.glb, .gltf, .obj, .ply, any case), or nothing.
std::optional<MeshFormat> meshFormatOf(std::string_view fileName);

// InputError (Inputs.h) for a file that is not a mesh of `format` (a bad header, an index out
// of range, a buffer the file lacks, a non-finite coordinate), one without triangles, or more
// than Limits::maxTriangles / maxPoints.
TriangleMesh decodeMesh(std::string_view bytes, MeshFormat format, const Limits& limits = {});

} // namespace voxc::inputs

#pragma once
// Mesh files. Every writer goes through writeFileAtomically and throws UserError on failure.
#include "voxc/mesh/Mesh.h"

#include <string>

namespace voxc {

// Binary little-endian PLY: vertex x y z nx ny nz (float), face list uchar int vertex_indices.
void writePly(const std::string& path, const Mesh& mesh);
// Wavefront OBJ: `v`, `vn`, and `f a//a b//b c//c` with 1-based indices.
void writeObj(const std::string& path, const Mesh& mesh);
// Picks the format from the extension (.ply or .obj, any case); anything else is a UserError.
void writeMesh(const std::string& path, const Mesh& mesh);

// Reads the PLY subset writePly produces (triangles only); UserError on anything else.
Mesh readPly(const std::string& path);

} // namespace voxc

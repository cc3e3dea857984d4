#pragma once
// Mesh files. Every writer goes through writeFileAtomically and throws UserError on failure.
#include "voxc/mesh/Mesh.h"
#include "voxc/program/Program.h"

#include <span>
#include <string>

namespace voxc {

// `materials` names and colours the mesh's material ids (the program's declared materials); id 0
// is `none`, and an id not in the list is written as `material<id>`, both in neutral grey.

// Binary little-endian PLY: vertex x y z nx ny nz (float), and when the mesh has materials
// `uchar material` plus `uchar red green blue` (the material's colour, so viewers show it);
// face list uchar int vertex_indices, and with materials `uchar material` (the triangle's).
void writePly(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
// Wavefront OBJ: `v`, `vn`, and `f a//a b//b c//c` with 1-based indices. When the mesh has
// materials, faces are grouped by material (`g NAME` + `usemtl NAME`, ascending id) and
// `mtllib STEM.mtl` names a material library written beside the OBJ (before it), Kd = colour.
void writeObj(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
// Picks the format from the extension (.ply or .obj, any case); anything else is a UserError.
void writeMesh(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});

// Reads the PLY subset writePly produces (triangles only; vertex and triangle materials when the
// file has them); UserError on anything else.
Mesh readPly(const std::string& path);

} // namespace voxc

#pragma once
// Mesh files, written atomically (voxc/core/AtomicWrite.h); every writer throws UserError on
// failure. The overloads taking OutputFiles add the file(s) to a set the caller commits, so that
// a command's outputs appear together or not at all.
#include "voxc/core/AtomicWrite.h"
#include "voxc/mesh/Mesh.h"
#include "voxc/program/Program.h"

#include <span>
#include <string>

namespace voxc {

// `materials` names and colours the mesh's material ids (the program's declared materials); id 0
// is `none`, and an id not in the list is written as `material<id>`, both in neutral grey.

// Binary little-endian PLY: vertex x y z nx ny nz (float), and when the mesh has materials
// `uchar material` plus `uchar red green blue` (the material's colour in sRGB, as viewers read
// vertex colours);
// face list uchar int vertex_indices, and with materials `uchar material` (the triangle's).
void writePly(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
void writePly(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
// Wavefront OBJ: `v`, `vn`, and `f a//a b//b c//c` with 1-based indices. When the mesh has
// materials, faces are grouped by material (`g NAME` + `usemtl NAME`, ascending id) and
// `mtllib STEM.mtl` names a material library written beside the OBJ (objMaterialLibraryPath),
// Kd = colour in sRGB (as OBJ viewers read it). The two files are one set: the .mtl is renamed first, so an OBJ on disk never
// names a missing library, and a failure leaves both previous files as they were.
void writeObj(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
void writeObj(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
// glTF 2.0 binary: one node and mesh, one primitive per material id that has triangles (ascending
// id), all sharing POSITION (with exact float bounds),
// NORMAL; indices 16-bit up to 65,535 vertices, else 32-bit. Each glTF material has the voxc
// name, the material's colour as its base colour (linear, like voxc's colours), so no two
// materials are equal but for their names, and extras voxc_material_id / voxc_color.
// Y up and counter-clockwise front faces, as voxc meshes already are. Ordered for rendering with
// meshoptimizer: each primitive's triangles for a 16-entry FIFO vertex cache (windings kept), then the vertices
// in first-use order (unused ones left out); the same mesh, deterministically renumbered. An empty
// mesh is a scene without nodes and without a BIN chunk.
std::string encodeGlb(const Mesh& mesh, std::span<const Material> materials = {});
void writeGlb(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
void writeGlb(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
// Picks the format from the extension (.ply, .obj or .glb, any case); anything else is a UserError.
void writeMesh(const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});
void writeMesh(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials = {});

// The .mtl beside an OBJ: "dir/STEM.obj" -> "dir/STEM.mtl" (written only when the mesh has materials).
std::string objMaterialLibraryPath(const std::string& objPath);

// Reads the PLY subset writePly produces (triangles only; vertex and triangle materials when the
// file has them); UserError on anything else. `materials`, when given, receives each non-zero
// material id the vertices carry, ascending, named `material<id>`, with the colour the file gives
// it (the sRGB bytes decoded to linear: what `voxc render` draws a mesh file with).
Mesh readPly(const std::string& path, std::vector<Material>* materials = nullptr);

// Reads a mesh in any format voxc writes, by extension (any case): .ply (readPly), .obj (`v`,
// `vn`, `f` with any index form, polygons as fans, `usemtl` names with the Kd of the `mtllib`
// beside it, decoded from sRGB) and .glb/.gltf (tinygltf: every triangle primitive of the default
// scene, placed by its nodes' transforms; a material's id is voxc's voxc_material_id extra, else
// its index + 1, its colour the linear base colour). Where a file lacks normals, each vertex
// takes its triangles' area-weighted normal. `materials`, when given, receives each material id
// the file names with its name and linear colour. UserError on a file it cannot read.
Mesh readMesh(const std::string& path, std::vector<Material>* materials = nullptr);

} // namespace voxc

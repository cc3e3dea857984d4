#pragma once
// How exporters name and colour material ids, and when they write materials at all.
#include "voxc/mesh/Mesh.h"
#include "voxc/program/Program.h"

#include <span>
#include <string>

namespace voxc::mesh_export {

struct MaterialLook {
    std::string name;  // the declared name; `none` for id 0, `material<id>` for an undeclared id
    glm::vec3 color;   // the declared colour; neutral grey otherwise
};

MaterialLook lookOf(uint8_t id, std::span<const Material> materials);

// Colour channel as a byte: [0, 1] rounded to 0..255.
uint8_t colorByte(float channel);

// Declared colours are linear RGB (glTF's baseColorFactor takes them as they are). OBJ's Kd and
// PLY's vertex colours are read as sRGB by their viewers (assimp, three.js, MeshLab, Blender), so
// those files carry the sRGB encoding (IEC 61966-2-1) and their readers decode it.
float linearToSrgb(float linear);
float srgbToLinear(float srgb);

// Materials are written when the caller names some (a program that declares materials) or the
// mesh carries a non-zero id; a plain mesh keeps the plain format.
bool writesMaterials(const Mesh& mesh, std::span<const Material> materials);

// The mesh's per-vertex / per-triangle id, treating missing vectors (a hand-built mesh) as all 0.
uint8_t vertexMaterial(const Mesh& mesh, size_t vertex);
uint8_t triangleMaterial(const Mesh& mesh, size_t triangle);

} // namespace voxc::mesh_export

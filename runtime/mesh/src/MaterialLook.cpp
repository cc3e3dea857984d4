#include "MaterialLook.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace voxc::mesh_export {

MaterialLook lookOf(uint8_t id, std::span<const Material> materials) {
    const glm::vec3 grey(0.6f); // the language's default material colour
    if (id == kMaterialNone) return {"none", grey};
    for (const Material& material : materials)
        if (material.id == id) return {material.name, material.color};
    return {fmt::format("material{}", id), grey};
}

uint8_t colorByte(float channel) { return uint8_t(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f)); }

float linearToSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float srgb) {
    const float c = std::clamp(srgb, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

bool writesMaterials(const Mesh& mesh, std::span<const Material> materials) {
    auto nonZero = [](uint8_t id) { return id != kMaterialNone; };
    return !materials.empty() || std::any_of(mesh.vertexMaterials.begin(), mesh.vertexMaterials.end(), nonZero) ||
           std::any_of(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), nonZero);
}

uint8_t vertexMaterial(const Mesh& mesh, size_t vertex) {
    if (mesh.vertexMaterials.empty()) return kMaterialNone;
    VOXC_ASSERT(mesh.vertexMaterials.size() == mesh.positions.size());
    return mesh.vertexMaterials[vertex];
}

uint8_t triangleMaterial(const Mesh& mesh, size_t triangle) {
    if (mesh.triangleMaterials.empty()) return kMaterialNone;
    VOXC_ASSERT(mesh.triangleMaterials.size() * 3 == mesh.triangles.size());
    return mesh.triangleMaterials[triangle];
}

} // namespace voxc::mesh_export

#include "MaterialLook.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fmt/format.h>
#include <iterator>
#include <set>

namespace voxc {

namespace {

void appendFace(fmt::memory_buffer& out, const Mesh& mesh, size_t triangle) {
    const uint32_t a = mesh.triangles[triangle * 3] + 1, b = mesh.triangles[triangle * 3 + 1] + 1, c = mesh.triangles[triangle * 3 + 2] + 1;
    fmt::format_to(std::back_inserter(out), "f {}//{} {}//{} {}//{}\n", a, a, b, b, c, c);
}

// One `newmtl` per id the faces use, ascending; Kd is the only property viewers need here, in
// sRGB as OBJ readers take it.
std::string materialLibrary(const std::set<uint8_t>& ids, std::span<const Material> materials) {
    fmt::memory_buffer out;
    fmt::format_to(std::back_inserter(out), "# voxc materials\n");
    for (uint8_t id : ids) {
        const mesh_export::MaterialLook look = mesh_export::lookOf(id, materials);
        fmt::format_to(std::back_inserter(out), "newmtl {}\nKd {} {} {}\n", look.name, mesh_export::linearToSrgb(look.color.r),
                       mesh_export::linearToSrgb(look.color.g), mesh_export::linearToSrgb(look.color.b));
    }
    return std::string(out.data(), out.size());
}

} // namespace

void writeObj(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    VOXC_ASSERT(mesh.normals.size() == mesh.positions.size() && mesh.triangles.size() % 3 == 0);
    const size_t triangleCount = mesh.triangles.size() / 3;
    const bool withMaterials = mesh_export::writesMaterials(mesh, materials);
    std::set<uint8_t> ids;
    if (withMaterials)
        for (size_t t = 0; t < triangleCount; ++t) ids.insert(mesh_export::triangleMaterial(mesh, t));

    fmt::memory_buffer out;
    fmt::format_to(std::back_inserter(out), "# voxc mesh: {} vertices, {} triangles\n", mesh.positions.size(), triangleCount);
    const std::string libraryPath = objMaterialLibraryPath(path);
    if (withMaterials)
        fmt::format_to(std::back_inserter(out), "mtllib {}\n", std::filesystem::path(libraryPath).filename().string());
    // {} prints the shortest text that reads back as the same float.
    for (const glm::vec3& p : mesh.positions) fmt::format_to(std::back_inserter(out), "v {} {} {}\n", p.x, p.y, p.z);
    for (const glm::vec3& n : mesh.normals) fmt::format_to(std::back_inserter(out), "vn {} {} {}\n", n.x, n.y, n.z);
    if (!withMaterials) {
        for (size_t t = 0; t < triangleCount; ++t) appendFace(out, mesh, t);
    } else {
        for (uint8_t id : ids) {
            const std::string name = mesh_export::lookOf(id, materials).name;
            fmt::format_to(std::back_inserter(out), "g {}\nusemtl {}\n", name, name);
            for (size_t t = 0; t < triangleCount; ++t)
                if (mesh_export::triangleMaterial(mesh, t) == id) appendFace(out, mesh, t);
        }
    }
    // The library first: the set renames in order, so an OBJ on disk never names a missing .mtl.
    if (withMaterials) outputs.add(libraryPath, materialLibrary(ids, materials));
    outputs.add(path, std::string_view(out.data(), out.size()));
}

void writeObj(const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    OutputFiles outputs;
    writeObj(outputs, path, mesh, materials);
    outputs.commit();
}

std::string objMaterialLibraryPath(const std::string& objPath) {
    const std::filesystem::path obj(objPath);
    return (obj.parent_path() / (obj.stem().string() + ".mtl")).string();
}

void writeMesh(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".ply") return writePly(outputs, path, mesh, materials);
    if (extension == ".obj") return writeObj(outputs, path, mesh, materials);
    if (extension == ".glb") return writeGlb(outputs, path, mesh, materials);
    throw UserError(fmt::format("unknown mesh format '{}' for '{}' (use .ply, .obj or .glb)", extension, path));
}

void writeMesh(const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    OutputFiles outputs;
    writeMesh(outputs, path, mesh, materials);
    outputs.commit();
}

} // namespace voxc

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fmt/format.h>
#include <iterator>

namespace voxc {

void writeObj(const std::string& path, const Mesh& mesh) {
    VOXC_ASSERT(mesh.normals.size() == mesh.positions.size() && mesh.triangles.size() % 3 == 0);
    fmt::memory_buffer out;
    fmt::format_to(std::back_inserter(out), "# voxc surface nets: {} vertices, {} triangles\n", mesh.positions.size(),
                   mesh.triangles.size() / 3);
    // {} prints the shortest text that reads back as the same float.
    for (const glm::vec3& p : mesh.positions) fmt::format_to(std::back_inserter(out), "v {} {} {}\n", p.x, p.y, p.z);
    for (const glm::vec3& n : mesh.normals) fmt::format_to(std::back_inserter(out), "vn {} {} {}\n", n.x, n.y, n.z);
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const uint32_t a = mesh.triangles[t] + 1, b = mesh.triangles[t + 1] + 1, c = mesh.triangles[t + 2] + 1;
        fmt::format_to(std::back_inserter(out), "f {}//{} {}//{} {}//{}\n", a, a, b, b, c, c);
    }
    writeFileAtomically(path, std::string(out.data(), out.size()));
}

void writeMesh(const std::string& path, const Mesh& mesh) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".ply") return writePly(path, mesh);
    if (extension == ".obj") return writeObj(path, mesh);
    throw UserError(fmt::format("unknown mesh format '{}' for '{}' (use .ply or .obj)", extension, path));
}

} // namespace voxc

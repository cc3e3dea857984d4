#include "MaterialLook.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"

#include <array>
#include <bit>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <span>
#include <sstream>

namespace voxc {

static_assert(std::endian::native == std::endian::little, "PLY I/O writes host floats and ints as little-endian");

namespace {

constexpr const char* kVertexProperties[] = {"x", "y", "z", "nx", "ny", "nz"};
// With materials each vertex also has its id and its material's colour (read by mesh viewers).
constexpr const char* kMaterialProperties[] = {"material", "red", "green", "blue"};
constexpr size_t kVertexBytes = 24, kMaterialBytes = 4, kFaceBytes = 13, kFaceMaterialBytes = 1;

std::string plyHeader(size_t vertexCount, size_t faceCount, bool materials) {
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment voxc mesh\n";
    header += fmt::format("element vertex {}\n", vertexCount);
    for (const char* name : kVertexProperties) header += fmt::format("property float {}\n", name);
    if (materials)
        for (const char* name : kMaterialProperties) header += fmt::format("property uchar {}\n", name);
    header += fmt::format("element face {}\nproperty list uchar int vertex_indices\n", faceCount);
    // ...and each face the material of the grid edge it crosses (Mesh::triangleMaterials).
    if (materials) header += "property uchar material\n";
    header += "end_header\n";
    return header;
}

template <typename T>
void append(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

[[noreturn]] void malformed(const std::string& path, const std::string& why) {
    throw UserError(fmt::format("'{}' is not a voxc PLY mesh: {}", path, why));
}

// Reads the next header line, skipping comments.
std::string headerLine(std::istringstream& header, const std::string& path) {
    std::string line;
    do {
        if (!std::getline(header, line)) malformed(path, "header ends early");
    } while (line.rfind("comment", 0) == 0);
    return line;
}

size_t elementCount(const std::string& line, const std::string& element, const std::string& path) {
    const std::string prefix = "element " + element + " ";
    if (line.rfind(prefix, 0) != 0) malformed(path, fmt::format("expected '{}<count>', got '{}'", prefix, line));
    const std::string digits = line.substr(prefix.size());
    if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos)
        malformed(path, fmt::format("bad {} count '{}'", element, digits));
    return size_t(std::stoull(digits));
}

void expectLine(const std::string& line, const std::string& expected, const std::string& path) {
    if (line != expected) malformed(path, fmt::format("expected '{}', got '{}'", expected, line));
}

} // namespace

void writePly(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    VOXC_ASSERT(mesh.normals.size() == mesh.positions.size() && mesh.triangles.size() % 3 == 0);
    const bool withMaterials = mesh_export::writesMaterials(mesh, materials);
    std::string bytes = plyHeader(mesh.positions.size(), mesh.triangles.size() / 3, withMaterials);
    bytes.reserve(bytes.size() + mesh.positions.size() * (kVertexBytes + kMaterialBytes) + mesh.triangles.size() / 3 * kFaceBytes);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        for (int a = 0; a < 3; ++a) append(bytes, mesh.positions[v][a]);
        for (int a = 0; a < 3; ++a) append(bytes, mesh.normals[v][a]);
        if (!withMaterials) continue;
        const uint8_t id = mesh_export::vertexMaterial(mesh, v);
        const glm::vec3 color = mesh_export::lookOf(id, materials).color;
        append(bytes, id);
        for (int c = 0; c < 3; ++c) append(bytes, mesh_export::colorByte(mesh_export::linearToSrgb(color[c])));
    }
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
        append(bytes, uint8_t(3));
        for (size_t k = 0; k < 3; ++k) append(bytes, int32_t(mesh.triangles[t + k]));
        if (withMaterials) append(bytes, mesh_export::triangleMaterial(mesh, t / 3));
    }
    outputs.add(path, bytes);
}

void writePly(const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    OutputFiles outputs;
    writePly(outputs, path, mesh, materials);
    outputs.commit();
}

Mesh readPly(const std::string& path, std::vector<Material>* materials) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(fmt::format("cannot read '{}'", path));
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string endHeader = "end_header\n";
    const size_t headerEnd = bytes.find(endHeader);
    if (bytes.rfind("ply\n", 0) != 0 || headerEnd == std::string::npos) malformed(path, "no PLY header");
    std::istringstream header(bytes.substr(4, headerEnd - 4));

    expectLine(headerLine(header, path), "format binary_little_endian 1.0", path);
    const size_t vertexCount = elementCount(headerLine(header, path), "vertex", path);
    for (const char* name : kVertexProperties) expectLine(headerLine(header, path), fmt::format("property float {}", name), path);
    std::string line = headerLine(header, path);
    const bool withMaterials = line == "property uchar material";
    if (withMaterials) {
        for (const char* name : std::span(kMaterialProperties).subspan(1))
            expectLine(headerLine(header, path), fmt::format("property uchar {}", name), path);
        line = headerLine(header, path);
    }
    const size_t faceCount = elementCount(line, "face", path);
    expectLine(headerLine(header, path), "property list uchar int vertex_indices", path);
    if (withMaterials) expectLine(headerLine(header, path), "property uchar material", path);

    const size_t dataStart = headerEnd + endHeader.size();
    const size_t vertexBytes = kVertexBytes + (withMaterials ? kMaterialBytes : 0);
    const size_t faceBytes = kFaceBytes + (withMaterials ? kFaceMaterialBytes : 0);
    if (bytes.size() - dataStart != vertexCount * vertexBytes + faceCount * faceBytes)
        malformed(path, "data size does not match the header");
    Mesh mesh;
    mesh.positions.resize(vertexCount);
    mesh.normals.resize(vertexCount);
    if (withMaterials) {
        mesh.vertexMaterials.resize(vertexCount);
        mesh.triangleMaterials.resize(faceCount);
    }
    const char* at = bytes.data() + dataStart;
    std::array<bool, 256> coloured{};
    std::array<glm::vec3, 256> found{};
    for (size_t v = 0; v < vertexCount; ++v) {
        std::memcpy(&mesh.positions[v], at, 12);
        std::memcpy(&mesh.normals[v], at + 12, 12);
        // The colour after the id is derived from it, so it is read back only when asked for.
        if (withMaterials) mesh.vertexMaterials[v] = uint8_t(at[kVertexBytes]);
        if (withMaterials && materials) {
            const uint8_t id = mesh.vertexMaterials[v];
            if (id != 0 && !coloured[id]) {
                coloured[id] = true;
                const auto channel = [&](int c) { return mesh_export::srgbToLinear(float(uint8_t(at[kVertexBytes + 1 + c])) / 255.0f); };
                found[id] = glm::vec3(channel(0), channel(1), channel(2));
            }
        }
        at += vertexBytes;
    }
    if (materials) {
        materials->clear();
        for (int id = 1; id < 256; ++id)
            if (coloured[id]) materials->push_back(Material{fmt::format("material{}", id), {}, uint8_t(id), found[id]});
    }
    mesh.triangles.reserve(faceCount * 3);
    for (size_t f = 0; f < faceCount; ++f) {
        if (uint8_t(*at) != 3) malformed(path, fmt::format("face {} is not a triangle", f));
        int32_t indices[3];
        std::memcpy(indices, at + 1, 12);
        if (withMaterials) mesh.triangleMaterials[f] = uint8_t(at[kFaceBytes]);
        at += faceBytes;
        for (int32_t index : indices) {
            if (index < 0 || size_t(index) >= vertexCount) malformed(path, fmt::format("face {} has vertex index {} out of range", f, index));
            mesh.triangles.push_back(uint32_t(index));
        }
    }
    return mesh;
}

} // namespace voxc

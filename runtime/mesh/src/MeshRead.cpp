#include "MaterialLook.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <iterator>
#include <map>
#include <sstream>
#include <tuple>
#include <tiny_gltf.h>

namespace voxc {

namespace {

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
    throw UserError(fmt::format("'{}' is not a mesh voxc can read: {}", path, what));
}

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(fmt::format("cannot read '{}'", path));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Where a file has no normals: each vertex's sum of its triangles' area-weighted normals.
void normalsFromFaces(Mesh& mesh) {
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
        const glm::vec3 f(triangleNormal(mesh, t));
        for (int k = 0; k < 3; ++k) mesh.normals[mesh.triangles[t * 3 + size_t(k)]] += f;
    }
    for (glm::vec3& n : mesh.normals)
        if (glm::length(n) > 0.0f) n = glm::normalize(n);
}

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
        const size_t start = at;
        while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at]))) ++at;
        if (at > start) out.push_back(line.substr(start, at - start));
    }
    return out;
}

float number(std::string_view word, const std::string& path, size_t line) {
    float value = 0.0f;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
        malformed(path, fmt::format("line {}: '{}' is not a finite number", line, word));
    return value;
}

// A 1-based (or negative, from the end) OBJ index into a list of `count`, as 0-based.
size_t objIndex(std::string_view word, size_t count, const std::string& path, size_t line) {
    long long index = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), index);
    if (error != std::errc() || end != word.data() + word.size()) malformed(path, fmt::format("line {}: bad index '{}'", line, word));
    const long long zeroBased = index < 0 ? (long long)count + index : index - 1;
    if (zeroBased < 0 || zeroBased >= (long long)count) malformed(path, fmt::format("line {}: index {} out of range", line, index));
    return size_t(zeroBased);
}

// `newmtl NAME` / `Kd R G B` (sRGB) from the library an OBJ names, by name.
std::map<std::string, glm::vec3> readMaterialLibrary(const std::string& path) {
    std::map<std::string, glm::vec3> colours;
    std::ifstream in(path);
    if (!in) return colours; // a missing library leaves the materials grey, as OBJ viewers do
    std::string line, current;
    size_t number_ = 0;
    while (std::getline(in, line)) {
        ++number_;
        const auto w = words(line);
        if (w.size() == 2 && w[0] == "newmtl") current = std::string(w[1]), colours[current] = glm::vec3(0.6f);
        else if (w.size() == 4 && w[0] == "Kd" && !current.empty())
            for (int c = 0; c < 3; ++c) colours[current][c] = mesh_export::srgbToLinear(number(w[size_t(c) + 1], path, number_));
    }
    return colours;
}

// OBJ: `v`, `vn`, `f` (any of a, a/b, a//c, a/b/c; polygons split into fans), `usemtl` and
// `mtllib`. A vertex is a distinct (position, normal, material): a point on a border between
// materials is drawn in each face's own, as the file assigns materials to faces.
Mesh readObj(const std::string& path, std::vector<Material>* materials) {
    std::istringstream in(readBytes(path));
    std::vector<glm::vec3> points, normals;
    std::map<std::tuple<size_t, size_t, uint8_t>, uint32_t> vertexOf;
    std::map<std::string, uint8_t> idOf;
    std::vector<std::string> names;
    std::string library, line;
    uint8_t material = 0;
    bool anyNormal = false, allNormals = true;
    Mesh mesh;
    for (size_t n = 1; std::getline(in, line); ++n) {
        const auto w = words(line);
        if (w.empty() || w[0].front() == '#') continue;
        if (w[0] == "v" && w.size() >= 4) {
            points.push_back({number(w[1], path, n), number(w[2], path, n), number(w[3], path, n)});
        } else if (w[0] == "vn" && w.size() >= 4) {
            normals.push_back({number(w[1], path, n), number(w[2], path, n), number(w[3], path, n)});
        } else if (w[0] == "mtllib" && w.size() >= 2) {
            library = (std::filesystem::path(path).parent_path() / std::string(w[1])).string();
        } else if (w[0] == "usemtl" && w.size() >= 2) {
            const std::string name(w[1]);
            if (!idOf.count(name)) {
                if (idOf.size() == 255) malformed(path, fmt::format("line {}: more than 255 materials", n));
                idOf[name] = uint8_t(idOf.size() + 1);
                names.push_back(name);
            }
            material = idOf[name];
        } else if (w[0] == "f") {
            if (w.size() < 4) malformed(path, fmt::format("line {}: a face needs three vertices", n));
            std::vector<uint32_t> corners;
            for (size_t k = 1; k < w.size(); ++k) {
                const std::string_view c = w[k];
                const size_t slash = c.find('/'), last = c.rfind('/');
                const size_t p = objIndex(c.substr(0, slash), points.size(), path, n);
                size_t normal = SIZE_MAX;
                if (slash != std::string_view::npos && last + 1 < c.size()) normal = objIndex(c.substr(last + 1), normals.size(), path, n);
                if (slash != std::string_view::npos && last == slash && slash + 1 < c.size()) normal = SIZE_MAX; // a/b: a texture index only
                anyNormal |= normal != SIZE_MAX;
                allNormals &= normal != SIZE_MAX;
                const auto [it, added] = vertexOf.try_emplace({p, normal, material}, uint32_t(mesh.positions.size()));
                if (added) {
                    mesh.positions.push_back(points[p]);
                    mesh.normals.push_back(normal == SIZE_MAX ? glm::vec3(0.0f) : normals[normal]);
                    mesh.vertexMaterials.push_back(material);
                }
                corners.push_back(it->second);
            }
            for (size_t k = 1; k + 1 < corners.size(); ++k) {
                mesh.triangles.insert(mesh.triangles.end(), {corners[0], corners[k], corners[k + 1]});
                mesh.triangleMaterials.push_back(material);
            }
        }
    }
    if (mesh.triangles.empty()) malformed(path, "no faces");
    if (!anyNormal || !allNormals) normalsFromFaces(mesh);
    if (materials) {
        materials->clear();
        const auto colours = library.empty() ? std::map<std::string, glm::vec3>{} : readMaterialLibrary(library);
        for (size_t i = 0; i < names.size(); ++i) {
            const auto c = colours.find(names[i]);
            materials->push_back(Material{names[i], {}, uint8_t(i + 1), c == colours.end() ? glm::vec3(0.6f) : c->second});
        }
    }
    return mesh;
}

// The float VEC3 or the index values of an accessor, honouring its view's stride.
template <typename Visit>
void forEachElement(const tinygltf::Model& model, int accessorIndex, const std::string& path, Visit visit) {
    if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size()) malformed(path, "an accessor index out of range");
    const tinygltf::Accessor& a = model.accessors[size_t(accessorIndex)];
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) malformed(path, "an accessor without a buffer view");
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) malformed(path, "a buffer view without a buffer");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) * size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
    const size_t stride = view.byteStride ? view.byteStride : size;
    const size_t start = view.byteOffset + a.byteOffset;
    if (a.count > 0 && (start + (a.count - 1) * stride + size > data.size() || start + (a.count - 1) * stride + size > view.byteOffset + view.byteLength))
        malformed(path, "an accessor runs past its buffer");
    for (size_t i = 0; i < a.count; ++i) visit(data.data() + start + i * stride, a.componentType, a.type);
}

std::vector<glm::vec3> vec3s(const tinygltf::Model& model, int accessor, const std::string& path) {
    std::vector<glm::vec3> out;
    forEachElement(model, accessor, path, [&](const unsigned char* at, int component, int type) {
        if (component != TINYGLTF_COMPONENT_TYPE_FLOAT || type != TINYGLTF_TYPE_VEC3) malformed(path, "POSITION or NORMAL is not float VEC3");
        glm::vec3 v;
        std::memcpy(&v, at, sizeof v);
        out.push_back(v);
    });
    return out;
}

std::vector<uint32_t> indices(const tinygltf::Model& model, int accessor, const std::string& path) {
    std::vector<uint32_t> out;
    forEachElement(model, accessor, path, [&](const unsigned char* at, int component, int) {
        if (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) out.push_back(*at);
        else if (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) { uint16_t v; std::memcpy(&v, at, 2); out.push_back(v); }
        else if (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) { uint32_t v; std::memcpy(&v, at, 4); out.push_back(v); }
        else malformed(path, "indices are not unsigned integers");
    });
    return out;
}

glm::mat4 nodeMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::mat4(glm::make_mat4(node.matrix.data()));
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    glm::dmat4 r(1.0);
    if (node.rotation.size() == 4) {
        const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        r = glm::dmat4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0, 2 * (x * y - z * w), 1 - 2 * (x * x + z * z),
                       2 * (y * z + x * w), 0, 2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0, 0, 0, 0, 1);
    }
    glm::dmat4 s(1.0);
    if (node.scale.size() == 3) s = glm::dmat4(node.scale[0], 0, 0, 0, 0, node.scale[1], 0, 0, 0, 0, node.scale[2], 0, 0, 0, 0, 1);
    return glm::mat4(m * r * s);
}

// glTF 2.0 (.glb, or .gltf with embedded buffers): every triangle primitive of the default
// scene's nodes, placed by their transforms; a material's id is its voxc_material_id extra when
// it has one (voxc's files), else its index + 1, its colour the base colour (linear).
Mesh readGltf(const std::string& path, std::vector<Material>* materials) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    const std::string bytes = readBytes(path);
    const std::string base = std::filesystem::path(path).parent_path().string();
    const bool ok = lowerExtension(path) == ".glb"
                        ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()), unsigned(bytes.size()), base)
                        : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), base);
    if (!ok) malformed(path, error.empty() ? "tinygltf could not parse it" : error);

    std::vector<uint8_t> idOf(model.materials.size(), 0);
    for (size_t m = 0; m < model.materials.size(); ++m) {
        const tinygltf::Value& extra = model.materials[m].extras;
        const bool tagged = extra.IsObject() && extra.Has("voxc_material_id") && extra.Get("voxc_material_id").IsNumber();
        const double id = tagged ? extra.Get("voxc_material_id").GetNumberAsDouble() : double(m + 1);
        idOf[m] = uint8_t(std::clamp(id, 0.0, 255.0));
        if (materials && idOf[m] != 0) {
            const auto& f = model.materials[m].pbrMetallicRoughness.baseColorFactor;
            materials->push_back(Material{model.materials[m].name, {}, idOf[m], glm::vec3(float(f[0]), float(f[1]), float(f[2]))});
        }
    }
    Mesh mesh;
    bool allNormals = true;
    std::vector<std::pair<int, glm::mat4>> stack;
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(scene) < model.scenes.size())
        for (int n : model.scenes[size_t(scene)].nodes) stack.push_back({n, glm::mat4(1.0f)});
    for (size_t visited = 0; !stack.empty(); ++visited) {
        const auto [n, parent] = stack.back();
        stack.pop_back();
        if (n < 0 || size_t(n) >= model.nodes.size() || visited > model.nodes.size()) malformed(path, "a node index out of range or a node cycle");
        const tinygltf::Node& node = model.nodes[size_t(n)];
        const glm::mat4 matrix = parent * nodeMatrix(node);
        for (int child : node.children) stack.push_back({child, matrix});
        if (node.mesh < 0) continue;
        if (size_t(node.mesh) >= model.meshes.size()) malformed(path, "a mesh index out of range");
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(matrix));
        for (const tinygltf::Primitive& p : model.meshes[size_t(node.mesh)].primitives) {
            if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) continue; // points and lines have no surface
            const auto position = p.attributes.find("POSITION");
            if (position == p.attributes.end()) malformed(path, "a primitive without POSITION");
            const std::vector<glm::vec3> points = vec3s(model, position->second, path);
            const auto normal = p.attributes.find("NORMAL");
            const std::vector<glm::vec3> normals = normal == p.attributes.end() ? std::vector<glm::vec3>{} : vec3s(model, normal->second, path);
            allNormals &= normals.size() == points.size();
            std::vector<uint32_t> corners;
            if (p.indices >= 0) corners = indices(model, p.indices, path);
            else for (uint32_t i = 0; i < points.size(); ++i) corners.push_back(i);
            const uint8_t material = p.material >= 0 && size_t(p.material) < idOf.size() ? idOf[size_t(p.material)] : 0;
            // Only the vertices the primitive's triangles use, each once per primitive: a vertex on
            // a border between materials is drawn in each triangle's own.
            std::vector<uint32_t> placed(points.size(), UINT32_MAX);
            for (size_t c = 0; c + 2 < corners.size(); c += 3) {
                for (int k = 0; k < 3; ++k) {
                    const uint32_t local = corners[c + size_t(k)];
                    if (local >= points.size()) malformed(path, "an index past its primitive's vertices");
                    if (placed[local] == UINT32_MAX) {
                        placed[local] = uint32_t(mesh.positions.size());
                        mesh.positions.push_back(glm::vec3(matrix * glm::vec4(points[local], 1.0f)));
                        mesh.normals.push_back(local < normals.size() ? glm::normalize(normalMatrix * normals[local]) : glm::vec3(0.0f));
                        mesh.vertexMaterials.push_back(material);
                    }
                    mesh.triangles.push_back(placed[local]);
                }
                mesh.triangleMaterials.push_back(material);
            }
        }
    }
    if (mesh.triangles.empty()) malformed(path, "no triangles");
    if (!allNormals) normalsFromFaces(mesh);
    return mesh;
}

} // namespace

Mesh readMesh(const std::string& path, std::vector<Material>* materials) {
    if (materials) materials->clear();
    const std::string ext = lowerExtension(path);
    if (ext == ".ply") return readPly(path, materials);
    if (ext == ".obj") return readObj(path, materials);
    if (ext == ".glb" || ext == ".gltf") return readGltf(path, materials);
    throw UserError(fmt::format("'{}': a mesh file must end in .ply, .obj, .glb or .gltf", path));
}

} // namespace voxc

#include "voxc/generators/inputs/MeshFile.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>

namespace voxc::inputs {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(uint8_t(c)));
    return out;
}

// Collects points and triangles under the limits; every coordinate finite.
class MeshBuilder {
public:
    explicit MeshBuilder(const Limits& limits) : limits_(limits) {}

    uint32_t point(glm::dvec3 p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            malformed(fmt::format("vertex {} is not finite ({}, {}, {})", mesh_.points.size(), p.x, p.y, p.z));
        if (int64_t(mesh_.points.size()) >= limits_.maxPoints)
            throw InputError("E0012", fmt::format("the mesh has more than {} vertices", limits_.maxPoints));
        mesh_.points.push_back(p);
        return uint32_t(mesh_.points.size() - 1);
    }
    void triangle(uint64_t a, uint64_t b, uint64_t c) {
        const uint64_t n = mesh_.points.size();
        if (a >= n || b >= n || c >= n)
            malformed(fmt::format("triangle {} names vertex {}, but there are {}", mesh_.triangles.size(),
                                  std::max({a, b, c}), n));
        if (int64_t(mesh_.triangles.size()) >= limits_.maxTriangles)
            throw InputError("E0012", fmt::format("the mesh has more than {} triangles", limits_.maxTriangles));
        mesh_.triangles.push_back({uint32_t(a), uint32_t(b), uint32_t(c)});
    }
    size_t pointCount() const { return mesh_.points.size(); }
    TriangleMesh take() {
        if (mesh_.triangles.empty()) malformed("the file holds no triangles");
        return std::move(mesh_);
    }

private:
    const Limits& limits_;
    TriangleMesh mesh_;
};

// ---- glTF (tinygltf) ----

// Images are not needed: skipped without decoding. External files are not read: a .vox names
// one file, which the package and the depfile track.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}
// Every file "exists", so tinygltf asks readNoFile for it, which refuses it and keeps its name
// (user data: the names asked for) for the error.
bool anyFileExists(const std::string&, void*) { return true; }
std::string keepPath(const std::string& path, void*) { return path; }
bool readNoFile(std::vector<unsigned char>*, std::string* error, const std::string& path, void* asked) {
    static_cast<std::vector<std::string>*>(asked)->push_back(path);
    *error = "not read";
    return false;
}
bool writeNoFile(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

uint32_t littleEndian32(std::string_view bytes, size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) v |= uint32_t(uint8_t(bytes[at + i])) << (8 * i);
    return v;
}

// A .glb's framing, checked before tinygltf reads it, so a file cut short says so. Returns
// whether a BIN chunk follows the JSON chunk.
bool checkGlbFraming(std::string_view bytes) {
    if (bytes.size() < 20) malformed(fmt::format("the .glb file ends inside its 20-byte header, at {} bytes (truncated)", bytes.size()));
    const uint32_t length = littleEndian32(bytes, 8);
    if (length > bytes.size())
        malformed(fmt::format("the .glb file holds {} bytes where its header says {} (truncated)", bytes.size(), length));
    const uint64_t binAt = 20 + uint64_t(littleEndian32(bytes, 12));
    if (binAt > length) malformed("the .glb's JSON chunk runs past the file's end (truncated)");
    return binAt + 8 <= length && bytes.substr(size_t(binAt) + 4, 4) == std::string_view("BIN\0", 4);
}

// The bytes of accessor `index` as `count` elements of `components` components of
// `componentSize` bytes, checked against its buffer view and buffer.
struct AccessorView {
    const unsigned char* data;
    size_t count, stride;
    int componentType;
};

AccessorView accessorView(const tinygltf::Model& model, int index, int type, std::string_view what) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        malformed(fmt::format("the {} accessor {} does not exist", what, index));
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    if (accessor.type != type) malformed(fmt::format("the {} accessor {} has the wrong type", what, index));
    if (accessor.sparse.isSparse) throw InputError("E0010", fmt::format("the {} accessor {} is sparse", what, index));
    if (accessor.bufferView < 0 || size_t(accessor.bufferView) >= model.bufferViews.size())
        malformed(fmt::format("the {} accessor {} has no buffer view", what, index));
    const tinygltf::BufferView& view = model.bufferViews[size_t(accessor.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        malformed(fmt::format("buffer view {} names buffer {}, which the file lacks", accessor.bufferView, view.buffer));
    const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType));
    const int components = tinygltf::GetNumComponentsInType(uint32_t(type));
    if (componentSize <= 0 || components <= 0) malformed(fmt::format("the {} accessor {} has an unknown component type", what, index));
    const size_t element = size_t(componentSize) * size_t(components);
    const size_t stride = view.byteStride ? view.byteStride : element;
    const size_t count = accessor.count;
    const size_t needed = count == 0 ? 0 : accessor.byteOffset + stride * (count - 1) + element;
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset ||
        needed > view.byteLength || stride < element)
        malformed(fmt::format("the {} accessor {} reaches past its buffer ({} bytes): the buffer is missing or short",
                              what, index, buffer.data.size()));
    return {buffer.data.data() + view.byteOffset + accessor.byteOffset, count, stride, accessor.componentType};
}

glm::dmat4 nodeMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m = m * glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

void addPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const glm::dmat4& matrix,
                  MeshBuilder& builder) {
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) return; // points and lines have no inside
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) malformed("a triangle primitive has no POSITION attribute");
    const AccessorView points = accessorView(model, position->second, TINYGLTF_TYPE_VEC3, "POSITION");
    if (points.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw InputError("E0010", "POSITION is not float (a quantised mesh); export it with float positions");
    const uint64_t first = builder.pointCount();
    for (size_t i = 0; i < points.count; ++i) {
        float p[3];
        std::memcpy(p, points.data + i * points.stride, sizeof p);
        builder.point(glm::dvec3(matrix * glm::dvec4(p[0], p[1], p[2], 1.0)));
    }
    if (primitive.indices < 0) {
        for (size_t i = 0; i + 2 < points.count; i += 3) builder.triangle(first + i, first + i + 1, first + i + 2);
        return;
    }
    const AccessorView indices = accessorView(model, primitive.indices, TINYGLTF_TYPE_SCALAR, "index");
    const auto index = [&](size_t i) -> uint64_t {
        const unsigned char* at = indices.data + i * indices.stride;
        switch (indices.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *at;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, at, 2); return v; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, at, 4); return v; }
        default: malformed("the indices are not unsigned integers");
        }
    };
    for (size_t i = 0; i + 2 < indices.count; i += 3)
        builder.triangle(first + index(i), first + index(i + 1), first + index(i + 2));
}

TriangleMesh decodeGltf(std::string_view bytes, const Limits& limits) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::vector<std::string> externalFiles; // an image's is skipped; a buffer's fails the load
    loader.SetFsCallbacks({anyFileExists, keepPath, readNoFile, writeNoFile, &externalFiles});
    tinygltf::Model model;
    std::string error, warning;
    const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
    const bool binChunk = binary && checkGlbFraming(bytes);
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                         reinterpret_cast<const unsigned char*>(bytes.data()),
                                                         unsigned(bytes.size()), "")
                           : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), "");
    if (!ok) {
        // A .vox names one file, which the package and the depfile track: no buffer beside it.
        for (const std::string& name : externalFiles)
            if (error.find("File read error : " + name) != std::string::npos)
                throw InputError("E0010", fmt::format("the glTF keeps a buffer in the external file '{}', which voxc "
                                                      "does not read; export a .glb (or a .gltf with its buffers "
                                                      "embedded)",
                                                      name));
        if (binary && !binChunk && error.find("BIN chunk") != std::string::npos)
            malformed("the .glb has no BIN chunk, but its JSON names a buffer stored there (a buffer the file lacks)");
        while (!error.empty() && std::isspace(uint8_t(error.back()))) error.pop_back();
        malformed(fmt::format("not a readable glTF: {}", error.empty() ? "unknown error" : error));
    }
    MeshBuilder builder(limits);
    std::vector<bool> visiting(model.nodes.size(), false);
    std::function<void(int, const glm::dmat4&)> visit = [&](int index, const glm::dmat4& parent) {
        if (index < 0 || size_t(index) >= model.nodes.size()) malformed(fmt::format("node {} does not exist", index));
        if (visiting[size_t(index)]) malformed(fmt::format("node {} is its own ancestor", index));
        visiting[size_t(index)] = true;
        const tinygltf::Node& node = model.nodes[size_t(index)];
        const glm::dmat4 matrix = parent * nodeMatrix(node);
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model.meshes.size()) malformed(fmt::format("node {} names mesh {}, which the file lacks", index, node.mesh));
            for (const tinygltf::Primitive& primitive : model.meshes[size_t(node.mesh)].primitives)
                addPrimitive(model, primitive, matrix, builder);
        }
        for (int child : node.children) visit(child, matrix);
        visiting[size_t(index)] = false;
    };
    if (!model.scenes.empty()) {
        const size_t scene = model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? size_t(model.defaultScene) : 0;
        for (int node : model.scenes[scene].nodes) visit(node, glm::dmat4(1.0));
    } else {
        for (const tinygltf::Mesh& mesh : model.meshes)
            for (const tinygltf::Primitive& primitive : mesh.primitives) addPrimitive(model, primitive, glm::dmat4(1.0), builder);
    }
    return builder.take();
}

// ---- OBJ ----

// One number of a record; E0102 naming the line when it is not one.
double parseNumber(std::string_view token, size_t line) {
    double v = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (error != std::errc() || end != token.data() + token.size())
        malformed(fmt::format("line {}: '{}' is not a number", line, token));
    return v;
}

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(uint8_t(line[i]))) ++i;
        const size_t start = i;
        while (i < line.size() && !std::isspace(uint8_t(line[i]))) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

TriangleMesh decodeObj(std::string_view bytes, const Limits& limits) {
    MeshBuilder builder(limits);
    size_t lineNumber = 0, start = 0;
    std::vector<int64_t> face;
    while (start < bytes.size()) {
        size_t end = bytes.find('\n', start);
        if (end == std::string_view::npos) end = bytes.size();
        const std::string_view line = bytes.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        const std::vector<std::string_view> words = splitWords(line);
        if (words.empty() || words[0][0] == '#') continue;
        if (words[0] == "v") {
            if (words.size() < 4) malformed(fmt::format("line {}: a vertex needs x y z", lineNumber));
            builder.point({parseNumber(words[1], lineNumber), parseNumber(words[2], lineNumber), parseNumber(words[3], lineNumber)});
        } else if (words[0] == "f") {
            face.clear();
            for (size_t k = 1; k < words.size(); ++k) {
                const std::string_view vertex = words[k].substr(0, words[k].find('/'));
                int64_t index = 0;
                const auto [p, error] = std::from_chars(vertex.data(), vertex.data() + vertex.size(), index);
                if (error != std::errc() || p != vertex.data() + vertex.size() || index == 0)
                    malformed(fmt::format("line {}: '{}' is not a vertex index", lineNumber, words[k]));
                // 1-based; negative counts back from the latest vertex.
                const int64_t resolved = index > 0 ? index - 1 : int64_t(builder.pointCount()) + index;
                if (resolved < 0 || resolved >= int64_t(builder.pointCount()))
                    malformed(fmt::format("line {}: vertex {} does not exist ({} so far)", lineNumber, index, builder.pointCount()));
                face.push_back(resolved);
            }
            if (face.size() < 3) malformed(fmt::format("line {}: a face needs three vertices", lineNumber));
            for (size_t k = 1; k + 1 < face.size(); ++k) builder.triangle(uint64_t(face[0]), uint64_t(face[k]), uint64_t(face[k + 1]));
        }
    }
    return builder.take();
}

// ---- PLY ----

struct PlyProperty {
    std::string name, type, countType; // countType: a list's count type, empty for a scalar
};
struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

size_t plyTypeSize(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

class PlyReader {
public:
    PlyReader(std::string_view bytes, size_t offset, bool ascii, bool bigEndian)
        : bytes_(bytes), at_(offset), ascii_(ascii), big_(bigEndian) {}

    double value(const std::string& type) {
        if (ascii_) {
            while (at_ < bytes_.size() && std::isspace(uint8_t(bytes_[at_]))) ++at_;
            const size_t start = at_;
            while (at_ < bytes_.size() && !std::isspace(uint8_t(bytes_[at_]))) ++at_;
            if (at_ == start) malformed("the PLY file ends inside its data (truncated)");
            return parseNumber(bytes_.substr(start, at_ - start), 0);
        }
        const size_t size = plyTypeSize(type);
        if (bytes_.size() - at_ < size) malformed("the PLY file ends inside its data (truncated)");
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + at_, size);
        at_ += size;
        if (big_) std::reverse(raw, raw + size);
        const auto as = [&](auto v) { std::memcpy(&v, raw, sizeof v); return double(v); };
        if (type == "char" || type == "int8") return as(int8_t());
        if (type == "uchar" || type == "uint8") return as(uint8_t());
        if (type == "short" || type == "int16") return as(int16_t());
        if (type == "ushort" || type == "uint16") return as(uint16_t());
        if (type == "int" || type == "int32") return as(int32_t());
        if (type == "uint" || type == "uint32") return as(uint32_t());
        if (type == "float" || type == "float32") return as(float());
        return as(double());
    }

private:
    std::string_view bytes_;
    size_t at_;
    bool ascii_, big_;
};

TriangleMesh decodePly(std::string_view bytes, const Limits& limits) {
    const size_t headerEnd = bytes.find("end_header");
    if (bytes.substr(0, 3) != "ply" || headerEnd == std::string_view::npos) malformed("not a PLY file (no 'ply' ... 'end_header')");
    size_t dataStart = bytes.find('\n', headerEnd);
    if (dataStart == std::string_view::npos) malformed("the PLY file ends after its header");
    ++dataStart;
    std::vector<PlyElement> elements;
    std::string format;
    size_t start = 0;
    while (start < headerEnd) {
        size_t end = bytes.find('\n', start);
        const std::vector<std::string_view> words = splitWords(bytes.substr(start, end - start));
        start = end + 1;
        if (words.empty()) continue;
        if (words[0] == "format" && words.size() >= 2) {
            format = words[1];
        } else if (words[0] == "element" && words.size() == 3) {
            PlyElement element;
            element.name = std::string(words[1]);
            const auto [p, error] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
            if (error != std::errc()) malformed(fmt::format("the PLY element '{}' has no count", words[1]));
            elements.push_back(std::move(element));
        } else if (words[0] == "property") {
            if (elements.empty()) malformed("a PLY property before any element");
            PlyProperty property;
            if (words.size() == 5 && words[1] == "list") property = {std::string(words[4]), std::string(words[3]), std::string(words[2])};
            else if (words.size() == 3) property = {std::string(words[2]), std::string(words[1]), ""};
            else malformed("a PLY property line is not 'property TYPE NAME' or 'property list COUNT TYPE NAME'");
            if (!plyTypeSize(property.type) || (!property.countType.empty() && !plyTypeSize(property.countType)))
                malformed(fmt::format("the PLY property '{}' has an unknown type", property.name));
            elements.back().properties.push_back(std::move(property));
        }
    }
    if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        malformed(fmt::format("unknown PLY format '{}'", format));
    for (const PlyElement& element : elements) {
        if (element.name == "vertex" && element.count > uint64_t(limits.maxPoints))
            throw InputError("E0012", fmt::format("the mesh has {} vertices, more than the limit of {}", element.count, limits.maxPoints));
        if (element.name == "face" && element.count > uint64_t(limits.maxTriangles))
            throw InputError("E0012", fmt::format("the mesh has {} faces, more than the limit of {} triangles", element.count, limits.maxTriangles));
        // Every element is at least one byte (or one character) per item: a count past the file
        // is a truncated file, found before reading.
        if (element.count > bytes.size()) malformed(fmt::format("the PLY element '{}' has more items than the file has bytes", element.name));
    }
    MeshBuilder builder(limits);
    PlyReader reader(bytes, dataStart, format == "ascii", format == "binary_big_endian");
    std::vector<double> face;
    for (const PlyElement& element : elements) {
        const bool isVertex = element.name == "vertex", isFace = element.name == "face";
        int axis[3] = {-1, -1, -1};
        if (isVertex) {
            for (size_t k = 0; k < element.properties.size(); ++k)
                for (int a = 0; a < 3; ++a)
                    if (element.properties[k].name == std::string(1, "xyz"[a]) && element.properties[k].countType.empty()) axis[a] = int(k);
            if (axis[0] < 0 || axis[1] < 0 || axis[2] < 0) malformed("the PLY vertex element has no x, y and z");
        }
        for (uint64_t item = 0; item < element.count; ++item) {
            glm::dvec3 p(0.0);
            for (size_t k = 0; k < element.properties.size(); ++k) {
                const PlyProperty& property = element.properties[k];
                if (property.countType.empty()) {
                    const double v = reader.value(property.type);
                    for (int a = 0; a < 3; ++a)
                        if (axis[a] == int(k)) p[a] = v;
                    continue;
                }
                const double count = reader.value(property.countType);
                if (!(count >= 0 && count <= 1024)) malformed(fmt::format("a PLY list of {} entries", count));
                face.clear();
                for (int i = 0; i < int(count); ++i) face.push_back(reader.value(property.type));
                if (!isFace || (property.name != "vertex_indices" && property.name != "vertex_index")) continue;
                if (face.size() < 3) malformed(fmt::format("PLY face {} has fewer than three vertices", item));
                for (double index : face)
                    if (!(index >= 0 && index < double(builder.pointCount())))
                        malformed(fmt::format("PLY face {} names vertex {}, but there are {}", item, index, builder.pointCount()));
                for (size_t i = 1; i + 1 < face.size(); ++i)
                    builder.triangle(uint64_t(face[0]), uint64_t(face[i]), uint64_t(face[i + 1]));
            }
            if (isVertex) builder.point(p);
        }
    }
    return builder.take();
}

} // namespace

std::optional<MeshFormat> meshFormatOf(std::string_view fileName) {
    const size_t dot = fileName.rfind('.');
    if (dot == std::string_view::npos) return std::nullopt;
    const std::string extension = lower(fileName.substr(dot + 1));
    if (extension == "glb" || extension == "gltf") return MeshFormat::Gltf;
    if (extension == "obj") return MeshFormat::Obj;
    if (extension == "ply") return MeshFormat::Ply;
    return std::nullopt;
}

TriangleMesh decodeMesh(std::string_view bytes, MeshFormat format, const Limits& limits) {
    switch (format) {
    case MeshFormat::Gltf: return decodeGltf(bytes, limits);
    case MeshFormat::Obj: return decodeObj(bytes, limits);
    case MeshFormat::Ply: return decodePly(bytes, limits);
    }
    return {};
}

} // namespace voxc::inputs

// glTF 2.0 binary (.glb), written with nlohmann-json for the JSON chunk and by hand for the
// container (KhronosGroup/glTF Specification 2.0, "GLB File Format Specification").
#include "ChunkWorkers.h"
#include "MaterialLook.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"

#include <array>
#include <bit>
#include <cstring>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <map>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <thread>

namespace voxc {

static_assert(std::endian::native == std::endian::little, "GLB is little-endian; the writer copies host floats and ints");

namespace {

using Json = nlohmann::ordered_json;

constexpr uint32_t kGlbMagic = 0x46546C67, kGlbVersion = 2, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;
constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class BinaryBuffer {
public:
    // Appends `bytes` as a buffer view of its own, starting 4-byte aligned; returns its index.
    // Room for `size` more bytes and their padding, so that appending copies each byte once.
    void reserve(size_t size) { data_.reserve(size); }
    size_t addView(const void* bytes, size_t size, int target, Json& views) {
        data_.resize((data_.size() + 3) & ~size_t(3), 0);
        const size_t offset = data_.size();
        data_.append(static_cast<const char*>(bytes), size);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
        return views.size() - 1;
    }
    const std::string& data() const { return data_; }
    std::string take() && { return std::move(data_); }

private:
    std::string data_;
};

void appendUint32(std::string& out, uint32_t value) {
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    out.append(bytes, 4);
}

// Triangles of each material id with any, ascending id; each list in the mesh's own order.
std::map<uint8_t, std::vector<uint32_t>> trianglesByMaterial(const Mesh& mesh) {
    const size_t triangleCount = mesh.triangles.size() / 3;
    std::array<size_t, 256> counts{};
    for (size_t t = 0; t < triangleCount; ++t) ++counts[mesh_export::triangleMaterial(mesh, t)];
    std::array<std::vector<uint32_t>, 256> lists;
    for (size_t id = 0; id < 256; ++id) lists[id].reserve(counts[id] * 3);
    for (size_t t = 0; t < triangleCount; ++t) {
        std::vector<uint32_t>& indices = lists[mesh_export::triangleMaterial(mesh, t)];
        indices.insert(indices.end(), mesh.triangles.begin() + std::ptrdiff_t(3 * t), mesh.triangles.begin() + std::ptrdiff_t(3 * t + 3));
    }
    std::map<uint8_t, std::vector<uint32_t>> groups;
    for (size_t id = 0; id < 256; ++id)
        if (counts[id] != 0) groups.emplace(uint8_t(id), std::move(lists[id]));
    return groups;
}

// The vertex streams a .glb carries, in the order written.
struct VertexStreams {
    std::vector<glm::vec3> positions, normals;
};

// Triangles per block of the vertex-cache reordering. The mesher's triangles come in cell order,
// so a block's triangles are neighbours: each block reordered alone keeps almost all of the gain
// of reordering the whole list, its vertices fit the CPU's caches, and the blocks run on the
// workers (one call over a 512^3 grid's mesh took three times its extraction).
constexpr size_t kCacheBlockTriangles = 16384;

// Reorders `indices` (triangles) for a 16-entry FIFO vertex cache, block by block (meshoptimizer
// over block-local vertex numbers); windings kept, and the result does not depend on the threads.
void optimizeVertexCache(std::vector<uint32_t>& indices, size_t vertexCount) {
    const size_t blockIndices = kCacheBlockTriangles * 3;
    const size_t blocks = (indices.size() + blockIndices - 1) / blockIndices;
    const size_t workers = std::min<size_t>(blocks, std::max(1u, std::thread::hardware_concurrency()));
    std::vector<uint32_t> ordered(indices.size());
    forEachChunk(workers, [&](size_t worker) {
        // Block-local number of each vertex while its block is reordered, else none.
        std::vector<uint32_t> localOf(vertexCount, UINT32_MAX);
        std::vector<uint32_t> globalOf, local;
        for (size_t b = worker; b < blocks; b += workers) {
            const size_t first = b * blockIndices, count = std::min(blockIndices, indices.size() - first);
            globalOf.clear();
            local.resize(count);
            for (size_t i = 0; i < count; ++i) {
                uint32_t& l = localOf[indices[first + i]];
                if (l == UINT32_MAX) {
                    l = uint32_t(globalOf.size());
                    globalOf.push_back(indices[first + i]);
                }
                local[i] = l;
            }
            uint32_t* out = ordered.data() + first;
            meshopt_optimizeVertexCacheFifo(out, local.data(), count, globalOf.size(), 16);
            for (size_t i = 0; i < count; ++i) out[i] = globalOf[out[i]];
            for (uint32_t g : globalOf) localOf[g] = UINT32_MAX;
        }
        return true;
    });
    indices = std::move(ordered);
}

// Reorders for a GPU (meshoptimizer): each primitive's triangles for the post-transform vertex
// cache (windings kept), then the shared vertices in the order the primitives first use them.
VertexStreams optimizeForRendering(const Mesh& mesh, std::map<uint8_t, std::vector<uint32_t>>& groups) {
    const size_t vertexCount = mesh.positions.size();
    std::vector<uint32_t> all;
    all.reserve(mesh.triangles.size());
    for (auto& [id, indices] : groups) {
        optimizeVertexCache(indices, vertexCount);
        all.insert(all.end(), indices.begin(), indices.end());
    }
    std::vector<uint32_t> remap(vertexCount);
    const size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), all.data(), all.size(), vertexCount);
    VertexStreams streams{std::vector<glm::vec3>(used), std::vector<glm::vec3>(used)};
    for (size_t v = 0; v < vertexCount; ++v) {
        if (remap[v] == ~0u) continue; // used by no triangle: left out
        streams.positions[remap[v]] = mesh.positions[v];
        streams.normals[remap[v]] = mesh.normals[v];
    }
    for (auto& [id, indices] : groups)
        for (uint32_t& i : indices) i = remap[i];
    return streams;
}

Json gltfDocument(const Mesh& mesh, std::span<const Material> materials, BinaryBuffer& bin) {
    Json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "voxc"}};
    doc["scene"] = 0;
    if (mesh.triangles.empty()) { // a primitive needs indices, so an empty mesh is an empty scene
        doc["scenes"] = Json::array({Json::object()});
        return doc;
    }
    VOXC_ASSERT(mesh.normals.size() == mesh.positions.size());
    std::map<uint8_t, std::vector<uint32_t>> groups = trianglesByMaterial(mesh);
    const VertexStreams streams = optimizeForRendering(mesh, groups);
    const size_t vertexCount = streams.positions.size();
    Json views = Json::array(), accessors = Json::array();
    bin.reserve(vertexCount * 24 + mesh.triangles.size() * 4 + 4 * (groups.size() + 2));

    glm::vec3 lo = streams.positions[0], hi = streams.positions[0];
    for (const glm::vec3& p : streams.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // The bounds are the float extrema exactly: validators compare them with the data.
    auto bound = [](glm::vec3 v) { return Json::array({double(v.x), double(v.y), double(v.z)}); };
    accessors.push_back({{"bufferView", bin.addView(streams.positions.data(), vertexCount * 12, kArrayBuffer, views)},
                         {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"}, {"min", bound(lo)}, {"max", bound(hi)}});
    accessors.push_back({{"bufferView", bin.addView(streams.normals.data(), vertexCount * 12, kArrayBuffer, views)},
                         {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"}});
    // 16-bit indices while every index fits below the primitive-restart value 65535.
    const bool shortIndices = vertexCount <= 65535;
    Json primitives = Json::array(), gltfMaterials = Json::array();
    for (const auto& [id, indices] : groups) {
        size_t view;
        if (shortIndices) {
            const std::vector<uint16_t> narrow(indices.begin(), indices.end());
            view = bin.addView(narrow.data(), narrow.size() * 2, kElementArrayBuffer, views);
        } else {
            view = bin.addView(indices.data(), indices.size() * 4, kElementArrayBuffer, views);
        }
        accessors.push_back({{"bufferView", view}, {"componentType", shortIndices ? kUnsignedShort : kUnsignedInt},
                             {"count", indices.size()}, {"type", "SCALAR"}});
        const mesh_export::MaterialLook look = mesh_export::lookOf(id, materials);
        // The colour is the material's base colour (linear, as voxc's colours are): a primitive
        // per material carries it, and readers that merge materials equal in everything but the
        // name (assimp's post-processing) keep them apart. The id travels in extras.
        gltfMaterials.push_back({{"name", look.name},
                                 {"pbrMetallicRoughness", {{"baseColorFactor", {look.color.r, look.color.g, look.color.b, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
                                 {"extras", {{"voxc_material_id", id}, {"voxc_color", {look.color.r, look.color.g, look.color.b}}}}});
        primitives.push_back({{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                              {"indices", accessors.size() - 1}, {"material", gltfMaterials.size() - 1}, {"mode", 4}});
    }
    doc["scenes"] = Json::array({{{"nodes", {0}}}});
    doc["nodes"] = Json::array({{{"mesh", 0}}});
    doc["meshes"] = Json::array({{{"primitives", primitives}}});
    doc["materials"] = gltfMaterials;
    doc["accessors"] = accessors;
    doc["bufferViews"] = views;
    doc["buffers"] = Json::array({{{"byteLength", bin.data().size()}}});
    return doc;
}

} // namespace

std::string encodeGlb(const Mesh& mesh, std::span<const Material> materials) {
    BinaryBuffer bin;
    std::string json = gltfDocument(mesh, materials, bin).dump();
    json.resize((json.size() + 3) & ~size_t(3), ' ');
    std::string binary = std::move(bin).take();
    binary.resize((binary.size() + 3) & ~size_t(3), '\0');

    const size_t total = 12 + 8 + json.size() + (binary.empty() ? 0 : 8 + binary.size());
    if (total > UINT32_MAX) throw UserError(fmt::format("the mesh is too large for a .glb file ({} bytes; the limit is 4 GiB)", total));
    std::string out;
    out.reserve(total);
    appendUint32(out, kGlbMagic);
    appendUint32(out, kGlbVersion);
    appendUint32(out, uint32_t(total));
    appendUint32(out, uint32_t(json.size()));
    appendUint32(out, kJsonChunk);
    out += json;
    if (!binary.empty()) { // the spec asks to omit an empty BIN chunk
        appendUint32(out, uint32_t(binary.size()));
        appendUint32(out, kBinChunk);
        out += binary;
    }
    return out;
}

void writeGlb(OutputFiles& outputs, const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    outputs.add(path, encodeGlb(mesh, materials));
}

void writeGlb(const std::string& path, const Mesh& mesh, std::span<const Material> materials) {
    OutputFiles outputs;
    writeGlb(outputs, path, mesh, materials);
    outputs.commit();
}

} // namespace voxc

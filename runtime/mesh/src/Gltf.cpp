// glTF 2.0 binary (.glb), written with nlohmann-json for the JSON chunk and by hand for the
// container (KhronosGroup/glTF Specification 2.0, "GLB File Format Specification").
#include "ChunkWorkers.h"
#include "MaterialLook.h"
#include "voxc/core/Errors.h"
#include "voxc/core/HugePages.h"
#include "voxc/mesh/Export.h"

#include <array>
#include <bit>
#include <algorithm>
#include <cstring>
#include <functional>
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

// The BIN chunk as planned pieces: each view's offset and length are fixed when it is added (so
// the JSON can name them), and its bytes are written once, straight into the file's buffer.
class BinaryBuffer {
public:
    using Writer = std::function<void(char*)>;
    // A view of `size` bytes that `write` fills, starting 4-byte aligned; returns its index.
    size_t addView(size_t size, int target, Json& views, Writer write) {
        const size_t offset = (size_ + 3) & ~size_t(3);
        size_ = offset + size;
        pieces_.push_back({offset, std::move(write)});
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
        return views.size() - 1;
    }
    size_t size() const { return size_; }
    // Writes every view into `out` (size() bytes, zeroed: the padding stays 0).
    void writeTo(char* out) const {
        for (const Piece& piece : pieces_) piece.write(out + piece.offset);
    }

private:
    struct Piece {
        size_t offset;
        Writer write;
    };
    std::vector<Piece> pieces_;
    size_t size_ = 0;
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
    for (size_t id = 0; id < 256; ++id) {
        lists[id].reserve(counts[id] * 3);
        adviseHugePages(lists[id].data(), counts[id] * 3 * sizeof(uint32_t));
    }
    for (size_t t = 0; t < triangleCount; ++t) {
        std::vector<uint32_t>& indices = lists[mesh_export::triangleMaterial(mesh, t)];
        indices.insert(indices.end(), mesh.triangles.begin() + std::ptrdiff_t(3 * t), mesh.triangles.begin() + std::ptrdiff_t(3 * t + 3));
    }
    std::map<uint8_t, std::vector<uint32_t>> groups;
    for (size_t id = 0; id < 256; ++id)
        if (counts[id] != 0) groups.emplace(uint8_t(id), std::move(lists[id]));
    return groups;
}

// The order of the vertices in the file: the new index of each of the mesh's vertices (~0u for
// one that no triangle uses, left out), and how many are written.
struct VertexOrder {
    std::vector<uint32_t> remap;
    size_t used = 0;
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
    std::vector<uint32_t> ordered;
    resizeOnHugePages(ordered, indices.size());
    forEachChunk(workers, [&](size_t worker) {
        // Block-local number of each vertex while its block is reordered, else none.
        std::vector<uint32_t> localOf;
        localOf.reserve(vertexCount);
        adviseHugePages(localOf.data(), vertexCount * sizeof(uint32_t));
        localOf.assign(vertexCount, UINT32_MAX);
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
// cache (windings kept), then the shared vertices in the order the primitives first use them;
// the primitives' indices are renumbered to that order.
VertexOrder optimizeForRendering(const Mesh& mesh, std::map<uint8_t, std::vector<uint32_t>>& groups) {
    const size_t vertexCount = mesh.positions.size();
    std::vector<uint32_t> all;
    all.reserve(mesh.triangles.size());
    adviseHugePages(all.data(), mesh.triangles.size() * sizeof(uint32_t));
    for (auto& [id, indices] : groups) {
        optimizeVertexCache(indices, vertexCount);
        all.insert(all.end(), indices.begin(), indices.end());
    }
    VertexOrder order;
    resizeOnHugePages(order.remap, vertexCount);
    order.used = meshopt_optimizeVertexFetchRemap(order.remap.data(), all.data(), all.size(), vertexCount);
    for (auto& [id, indices] : groups)
        for (uint32_t& i : indices) i = order.remap[i];
    return order;
}

// A vertex stream in the file's order: each used vertex's value at its new index.
BinaryBuffer::Writer vertexStream(const std::vector<glm::vec3>& values, const std::vector<uint32_t>& remap) {
    return [&values, &remap](char* out) {
        for (size_t v = 0; v < values.size(); ++v)
            if (remap[v] != ~0u) std::memcpy(out + size_t(remap[v]) * sizeof(glm::vec3), &values[v], sizeof(glm::vec3));
    };
}

// The pieces of the BIN chunk (`order` and `groups`, which its views read when written) are kept
// by the caller until the views are written.
Json gltfDocument(const Mesh& mesh, std::span<const Material> materials, BinaryBuffer& bin, VertexOrder& order,
                  std::map<uint8_t, std::vector<uint32_t>>& groups) {
    Json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "voxc"}};
    doc["scene"] = 0;
    if (mesh.triangles.empty()) { // a primitive needs indices, so an empty mesh is an empty scene
        doc["scenes"] = Json::array({Json::object()});
        return doc;
    }
    VOXC_ASSERT(mesh.normals.size() == mesh.positions.size());
    groups = trianglesByMaterial(mesh);
    order = optimizeForRendering(mesh, groups);
    const size_t vertexCount = order.used;
    Json views = Json::array(), accessors = Json::array();

    // From the file's first vertex on, as a reader scanning the stream would.
    const size_t firstWritten = size_t(std::find(order.remap.begin(), order.remap.end(), 0u) - order.remap.begin());
    glm::vec3 lo = mesh.positions[firstWritten], hi = lo;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        if (order.remap[v] != ~0u) {
            lo = glm::min(lo, mesh.positions[v]);
            hi = glm::max(hi, mesh.positions[v]);
        }
    // The bounds are the float extrema exactly: validators compare them with the data.
    auto bound = [](glm::vec3 v) { return Json::array({double(v.x), double(v.y), double(v.z)}); };
    accessors.push_back({{"bufferView", bin.addView(vertexCount * 12, kArrayBuffer, views, vertexStream(mesh.positions, order.remap))},
                         {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"}, {"min", bound(lo)}, {"max", bound(hi)}});
    accessors.push_back({{"bufferView", bin.addView(vertexCount * 12, kArrayBuffer, views, vertexStream(mesh.normals, order.remap))},
                         {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"}});
    // 16-bit indices while every index fits below the primitive-restart value 65535.
    const bool shortIndices = vertexCount <= 65535;
    Json primitives = Json::array(), gltfMaterials = Json::array();
    for (const auto& [id, indices] : groups) {
        size_t view;
        if (shortIndices) {
            view = bin.addView(indices.size() * 2, kElementArrayBuffer, views, [&indices = indices](char* out) {
                for (size_t i = 0; i < indices.size(); ++i) {
                    const uint16_t narrow = uint16_t(indices[i]);
                    std::memcpy(out + 2 * i, &narrow, 2);
                }
            });
        } else {
            view = bin.addView(indices.size() * 4, kElementArrayBuffer, views,
                               [&indices = indices](char* out) { std::memcpy(out, indices.data(), indices.size() * 4); });
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
    doc["buffers"] = Json::array({{{"byteLength", bin.size()}}});
    return doc;
}

} // namespace

std::string encodeGlb(const Mesh& mesh, std::span<const Material> materials) {
    BinaryBuffer bin;
    VertexOrder order;
    std::map<uint8_t, std::vector<uint32_t>> groups;
    std::string json = gltfDocument(mesh, materials, bin, order, groups).dump();
    json.resize((json.size() + 3) & ~size_t(3), ' ');
    const size_t binarySize = (bin.size() + 3) & ~size_t(3);

    const size_t total = 12 + 8 + json.size() + (binarySize == 0 ? 0 : 8 + binarySize);
    if (total > UINT32_MAX) throw UserError(fmt::format("the mesh is too large for a .glb file ({} bytes; the limit is 4 GiB)", total));
    std::string out;
    out.reserve(total);
    adviseHugePages(out.data(), total);
    appendUint32(out, kGlbMagic);
    appendUint32(out, kGlbVersion);
    appendUint32(out, uint32_t(total));
    appendUint32(out, uint32_t(json.size()));
    appendUint32(out, kJsonChunk);
    out += json;
    if (binarySize != 0) { // the spec asks to omit an empty BIN chunk
        appendUint32(out, uint32_t(binarySize));
        appendUint32(out, kBinChunk);
        const size_t at = out.size();
        out.resize(total, '\0');
        bin.writeTo(out.data() + at);
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

// manifest.json: everything an engine needs to load and run a package without voxc's headers
// (docs/cli.md, "The manifest", documents it field by field).
#include <cctype>
#include "voxc/core/Sha256.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/Ir.h"

#include <algorithm>
#include <bit>
#include <fmt/format.h>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#ifndef VOXC_VERSION
#error "VOXC_VERSION must be defined by the build"
#endif

namespace voxc::codegen {

namespace {

using Json = nlohmann::ordered_json; // keys stay in the order written

// Bumped whenever a field changes meaning or goes away (adding fields keeps the version).
constexpr int kManifestSchemaVersion = 1;

Json vec(glm::ivec3 v) { return Json::array({v.x, v.y, v.z}); }

// A float as the shortest decimal that reads back as the same float (0.45, not the double
// 0.44999998807907104 that the float widens to).
Json floatJson(float value) { return std::stod(fmt::format("{}", value)); }

// log2 of the chunk size (a power of two).
int chunkShift(const World& world) { return std::countr_zero(uint32_t(world.chunkSize)); }

// World-aligned chunks covering the grid per axis, as the runtime's ChunkLayout lays them out
// (>> on a negative int is floor division).
glm::ivec3 chunkTableExtents(const World& world) {
    return ((world.origin + world.size - 1) >> chunkShift(world)) - (world.origin >> chunkShift(world)) + 1;
}

struct BufferInfo {
    const char* name;        // the GLSL block instance, e.g. "voxels"
    const char* elementType; // GLSL scalar type; every element is 4 bytes
    const char* countFormula;
    const char* meaning;
};

// Descriptor set 0 (KernelPackage.h): every storage buffer a kernel may declare.
BufferInfo bufferInfo(uint32_t binding) {
    switch (binding) {
    case kBindingVoxels:
        return {"voxels", "float", "chunk_slots * chunk^3",
                "voxel densities, chunk-major: chunk slot, then x fastest, then y, then z inside the chunk"};
    case kBindingChunkTable:
        return {"chunkTable", "int", "chunk_slots",
                "chunk-table entry (x fastest over world.chunk_table) -> chunk slot; voxc packs slot = entry"};
    case kBindingNoiseTables:
        return {"noiseTables", "int", "256", "Ken Perlin's permutation of 0..255, read by the noise functions"};
    case kBindingTileRanges:
        return {"tileRanges", "uint", "2 * tiles",
                "per tile: lowest and highest order-preserving density key; tiles = chunk_slots * (chunk >> "
                "tile_shift)^3, tile_shift (push anchorStep.w) chosen by the engine, at most log2(chunk)"};
    case kBindingTileDirty: return {"tileDirty", "uint", "tiles", "per tile: 1 when written since its range was computed"};
    case kBindingActiveTiles: return {"activeTiles", "uint", "tiles", "tile ids the current phase runs on"};
    case kBindingActiveDispatch:
        return {"activeDispatch", "uint", "8", "two VkDispatchIndirectCommand records (x, y, z) and each one's active tile count, written by the active-tiles kernels"};
    case kBindingSkipStats:
        return {"skipStats", "uint", "1", "the (tile, phase) pairs a run dispatched (statistics only)"};
    case kBindingTileOccupancy:
        return {"tileOccupancy", "uint", "tiles * (1 << tile_shift)^3 / 32 (1 when tile_shift > 4)",
                "per tile: a bit per voxel (x fastest, rows of 1 << tile_shift bits), set where the package's occupancy "
                "level holds (the kernels' occupied()); recomputed with the tile's range, kept exact by the sweeps"};
    case kBindingMaterials:
        return {"materials", "uint", "chunk_slots * chunk^3",
                "voxel material ids (0 = none, else materials[].id) at the densities' addresses"};
    case kBindingNonFinite:
        return {"nonFinite", "uint", "3",
                "the current stage's non-finite densities replaced by 0: count (low, high word), lowest grid index; "
                "the engine resets it to {0, 0, 0xffffffff} before each stage"};
    case kBindingPointSets:
        return {"pointSets", "int", "engine",
                "the package's point sets (an lsystem_cave's centres and skeleton segments) with, per 8^3 cell of "
                "the grid, the sorted lists of those whose reach meets the cell; layout in lsystem_carve.glsl"};
    case kBindingSolveTables:
        return {"solveTables", "int", "engine",
                "the curves stages' host-solved tables (density and material per cell of each solve box, computed "
                "when the file is checked); layout in solve_tables.glsl"};
    case kBindingScratch:
        return {"scratch", "uint", "engine: the largest scratch_words of a stage, at least 1",
                "words a stage's prepass_kernel hands to its grid pass: a speleothem stage's air mask, one bit per "
                "voxel, column (x, z) from word (x + size.x * z) * ceil(size.y / 32); layout in speleothem_air.glsl"};
    }
    throw InternalError(fmt::format("a kernel declares binding {}, which the manifest does not describe", binding));
}

// The element count for this package's grid, or null where the engine chooses (tile counts).
Json bufferCount(uint32_t binding, const World& world) {
    const glm::ivec3 extents = chunkTableExtents(world);
    const uint64_t chunkSlots = uint64_t(extents.x) * uint64_t(extents.y) * uint64_t(extents.z);
    const uint64_t chunkVoxels = uint64_t(world.chunkSize) * uint64_t(world.chunkSize) * uint64_t(world.chunkSize);
    switch (binding) {
    case kBindingVoxels:
    case kBindingMaterials: return chunkSlots * chunkVoxels;
    case kBindingChunkTable: return chunkSlots;
    case kBindingNoiseTables: return 256;
    case kBindingActiveDispatch: return 8;
    case kBindingSkipStats: return 1;
    case kBindingNonFinite: return 3;
    default: return nullptr;
    }
}

Json buffersJson(const KernelPackage& package) {
    std::set<uint32_t> declared;
    for (const Kernel& k : package.kernels)
        declared.insert(k.bindings.begin(), k.bindings.end());
    const std::vector<PackageData> data = packageData(package);
    Json buffers = Json::array();
    for (uint32_t binding : declared) {
        const BufferInfo info = bufferInfo(binding);
        const auto contents = std::find_if(data.begin(), data.end(), [&](const PackageData& d) { return d.binding == binding; });
        Json buffer{{"binding", binding},
                    {"name", info.name},
                    {"element_type", info.elementType},
                    {"element_bytes", 4},
                    {"count", contents != data.end() ? Json(contents->words.size()) : bufferCount(binding, package.world)},
                    {"count_formula", info.countFormula},
                    {"meaning", info.meaning}};
        // The words to upload, little endian, as the package holds them.
        if (contents != data.end()) buffer["file"] = contents->path;
        buffers.push_back(buffer);
    }
    return buffers;
}

// voxc::PushBlock, field by field (compiler/shaders/common.glsl), with what the engine puts there.
Json pushConstantsJson() {
    struct Field {
        const char* name;
        const char* meaning;
    };
    static constexpr Field fields[] = {
        {"gridOrigin", "xyz: world coordinate of grid voxel (0,0,0); w: chunk size"},
        {"gridSize", "xyz: grid size in voxels; w: seed (uint bit pattern)"},
        {"chunkBase", "xyz: world chunk coordinate of chunk-table entry 0; w: grammar iteration (from 0)"},
        {"chunkCount", "xyz: chunk-table extents; w: sweep index within its grammar"},
        {"anchorStart",
         "xyz: grid-local first anchor (start and field kernels: the box's min); w: active-dispatch record (0 or 1) "
         "of an active-tiles or indirect sweep dispatch; field kernel: the box's constant as float bits"},
        {"anchorStep", "xyz: distance between anchors of one phase (start and field kernels: 1); w: log2 tile size"},
        {"anchorCount",
         "xyz: anchors per axis in this dispatch (start and field kernels: the box's size); w: sweep: 1 when it "
         "runs indirectly over the active tiles, else 0; field kernel: 1 in a constant box, else 0"},
    };
    static_assert(sizeof(PushBlock) == std::size(fields) * 16);
    Json out = Json::array();
    for (size_t i = 0; i < std::size(fields); ++i)
        out.push_back(Json{{"name", fields[i].name}, {"offset", i * 16}, {"type", "ivec4"}, {"meaning", fields[i].meaning}});
    return Json{{"size", sizeof(PushBlock)}, {"fields", out}};
}

Json materialsJson(const KernelPackage& package) {
    Json materials = Json::array();
    for (const Material& m : package.materials)
        materials.push_back(Json{{"id", m.id}, {"name", m.name}, {"color", Json::array({floatJson(m.color.r), floatJson(m.color.g), floatJson(m.color.b)})}});
    return materials;
}

Json kernelJson(const Kernel& k) {
    return Json{{"name", k.name},
                {"origin", k.origin},
                {"glsl", packageGlslPath(k)},
                {"spv", packageSpirvPath(k)},
                {"local_size", Json::array({k.localSize[0], k.localSize[1], k.localSize[2]})},
                {"anchors_per_invocation",
                 Json::array({k.anchorsPerInvocation[0], k.anchorsPerInvocation[1], k.anchorsPerInvocation[2]})},
                {"bindings", k.bindings},
                {"spv_sha256", sha256Hex(littleEndianWords(k.spirv))}};
}

// The .vox first, then its rule files: the path the checker reads, the package's copy, its hash.
Json sourcesJson(const PackageSource& source) {
    Json sources = Json::array();
    if (source.fileName.empty()) return sources;
    sources.push_back(Json{{"path", source.fileName}, {"file", packageSourcePath(0)}, {"sha256", sha256Hex(source.text)}});
    for (size_t i = 0; i < source.imports.size(); ++i)
        sources.push_back(Json{{"path", source.imports[i].path},
                               {"file", packageSourcePath(i + 1, source.imports[i].path)},
                               {"sha256", sha256Hex(source.imports[i].text)}});
    return sources;
}

// The byte count of every file of the package but manifest.json, by path: a loader checks each
// file's size on disk against it before reading the file (a tampered file is refused unread).
Json fileSizesJson(const KernelPackage& package, const PackageSource& source) {
    std::map<std::string, uint64_t> sizes;
    for (const Kernel& k : package.kernels) {
        sizes[packageGlslPath(k)] = k.glsl.size();
        sizes[packageSpirvPath(k)] = 4 * uint64_t(k.spirv.size());
    }
    for (const PackageData& data : packageData(package)) sizes[data.path] = 4 * uint64_t(data.words.size());
    if (!source.fileName.empty()) {
        sizes[packageSourcePath(0)] = source.text.size();
        for (size_t i = 0; i < source.imports.size(); ++i) sizes[packageSourcePath(i + 1)] = source.imports[i].text.size();
    }
    Json files = Json::object();
    for (const auto& [path, bytes] : sizes) files[path] = bytes;
    return files;
}

// A kernel's name, or null for kNoKernel.
Json kernelName(const KernelPackage& package, uint32_t kernel) {
    return kernel == kNoKernel ? Json(nullptr) : Json(package.kernels.at(kernel).name);
}

Json sweepJson(const KernelPackage& package, const SweepPlan& sweep) {
    Json phases = Json::array();
    for (size_t p = 0; p < sweep.phaseStart.size(); ++p)
        phases.push_back(Json{{"start", vec(sweep.phaseStart[p])},
                              {"step", vec(sweep.phaseStep[p])},
                              {"count", vec(sweep.phaseCount3[p])}});
    return Json{{"kernel", package.kernels.at(sweep.kernel).name},
                {"active_tiles_kernel", kernelName(package, sweep.activeTilesKernel)},
                {"stamp_kernel", kernelName(package, sweep.stampKernel)},
                {"stamp_reach", vec(sweep.stampReach)},
                {"window", vec(sweep.window)},
                {"phase_count", vec(sweep.phaseCount)},
                {"phases", phases}};
}

// Whatever the kind: its attributes, the grid pass's kernel and boxes, the material, the sweeps.
Json stageJson(const KernelPackage& package, const StagePlan& stage) {
    Json json{{"kind", stage.kind}};
    for (const auto& [key, value] : stage.attributes) json[key] = value;
    if (stage.gridKernel != kNoKernel) {
        // Each box: [min, max] where the kernel is dispatched, [min, max, value] where a field is
        // that constant, [min, max, value, "unchanged"] where it is not dispatched at all; no
        // boxes: the whole grid.
        Json boxes = Json::array();
        for (const FieldBox& box : stage.gridBoxes) {
            Json entry = Json::array({{box.min.x, box.min.y, box.min.z}, {box.max.x, box.max.y, box.max.z}});
            if (box.constant) entry.push_back(floatJson(box.value));
            if (box.unchanged) entry.push_back("unchanged");
            boxes.push_back(entry);
        }
        json["kernel"] = package.kernels.at(stage.gridKernel).name;
        json["boxes"] = boxes;
    }
    // A pass over the whole grid before the grid pass, and the scratch words the passes share.
    if (stage.prepassKernel != kNoKernel) json["prepass_kernel"] = package.kernels.at(stage.prepassKernel).name;
    if (stage.scratchWords != 0) json["scratch_words"] = stage.scratchWords;
    // The material id the stage writes; absent: materials untouched.
    if (stage.material) json["material"] = *stage.material;
    if (stage.grammar) {
        Json sweeps = Json::array();
        for (const SweepPlan& sweep : stage.grammar->sweeps)
            sweeps.push_back(sweepJson(package, sweep));
        json["iterations"] = stage.grammar->iterations;
        json["sweeps"] = sweeps;
    }
    json["dependency_radius"] = vec(stage.dependencyRadius);
    return json;
}

} // namespace

std::string packageSourcePath(size_t index, std::string_view importPath) {
    if (index == 0) return "sources/0.vox";
    // A heightmap's or mesh's copy keeps its kind of extension, from a fixed list.
    const size_t dot = importPath.rfind('.');
    std::string extension = dot == std::string_view::npos ? "" : std::string(importPath.substr(dot + 1));
    for (char& c : extension) c = char(std::tolower(uint8_t(c)));
    for (std::string_view known : kPackageInputExtensions)
        if (extension == known) return fmt::format("sources/{}.{}", index, known);
    return fmt::format("sources/{}.rules", index);
}

std::string packageGlslPath(const Kernel& k) { return "kernels/" + k.name + ".comp"; }
std::string packageSpirvPath(const Kernel& k) { return "kernels/" + k.name + ".spv"; }

std::string packageManifest(const KernelPackage& package, const PackageSource& source) {
    const World& w = package.world;
    Json kernels = Json::array();
    for (const Kernel& k : package.kernels)
        kernels.push_back(kernelJson(k));
    Json stages = Json::array();
    for (const StagePlan& stage : package.stages)
        stages.push_back(stageJson(package, stage));
    const Json manifest{
        {"format", kPackageFormat},
        {"schema_version", kManifestSchemaVersion},
        {"voxc_version", VOXC_VERSION},
        {"source", Json{{"file", source.fileName}, {"sha256", sha256Hex(source.text)}}},
        {"sources", sourcesJson(source)},
        {"world", Json{{"size", vec(w.size)},
                       {"origin", vec(w.origin)},
                       {"chunk", w.chunkSize},
                       {"seed", w.seed},
                       {"halo", vec(package.halo)},
                       {"chunk_table", Json{{"base", vec(w.origin >> chunkShift(w))},
                                            {"count", vec(chunkTableExtents(w))}}}}},
        {"uses_materials", package.usesMaterials},
        {"materials", materialsJson(package)},
        {"push_constants", pushConstantsJson()},
        {"buffers", buffersJson(package)},
        {"kernels", kernels},
        {"dispatch", Json{{"tile_ranges_kernel", kernelName(package, package.tileRangesKernel)}, {"stages", stages}}},
        {"files", fileSizesJson(package, source)}};
    return manifest.dump(2) + "\n";
}

} // namespace voxc::codegen

#include "voxc/codegen/PackageWriter.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/Ir.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#ifndef VOXC_VERSION
#error "VOXC_VERSION must be defined by the build"
#endif

namespace voxc::codegen {

namespace {

using Json = nlohmann::ordered_json; // keys stay in the order written

Json vec(glm::ivec3 v) { return Json::array({v.x, v.y, v.z}); }

std::string glslPath(const Kernel& k) { return "kernels/" + k.name + ".comp"; }
std::string spirvPath(const Kernel& k) { return "kernels/" + k.name + ".spv"; }

// The interface every kernel declares in compiler/shaders/common.glsl.
Json bindings() {
    return Json::array({Json{{"binding", kBindingVoxels}, {"name", "density"}, {"type", "float[]"}},
                        Json{{"binding", kBindingChunkTable}, {"name", "chunkSlot"}, {"type", "int[]"}},
                        Json{{"binding", kBindingNoiseTables}, {"name", "perlinPermutation"}, {"type", "int[256]"}},
                        Json{{"binding", kBindingTileRanges}, {"name", "tileRanges"}, {"type", "uint[2 per tile]"}},
                        Json{{"binding", kBindingTileDirty}, {"name", "tileDirty"}, {"type", "uint[tiles]"}},
                        Json{{"binding", kBindingActiveTiles}, {"name", "activeTiles"}, {"type", "uint[tiles]"}},
                        Json{{"binding", kBindingActiveDispatch}, {"name", "activeDispatch"}, {"type", "uint[8]"}},
                        Json{{"binding", kBindingSkipStats}, {"name", "skipStats"}, {"type", "uint[2]"}}});
}

Json pushConstants() {
    const char* names[] = {"gridOrigin",  "gridSize",   "chunkBase",  "chunkCount",
                           "anchorStart", "anchorStep", "anchorCount"};
    static_assert(sizeof(PushBlock) == std::size(names) * 16);
    Json fields = Json::array();
    for (size_t i = 0; i < std::size(names); ++i)
        fields.push_back(Json{{"name", names[i]}, {"offset", i * 16}, {"type", "ivec4"}});
    return fields;
}

Json kernelJson(const Kernel& k) {
    return Json{{"name", k.name},
                {"origin", k.origin},
                {"glsl", glslPath(k)},
                {"spv", spirvPath(k)},
                {"local_size", Json::array({k.localSize[0], k.localSize[1], k.localSize[2]})},
                {"anchors_per_invocation",
                 Json::array({k.anchorsPerInvocation[0], k.anchorsPerInvocation[1], k.anchorsPerInvocation[2]})},
                {"bindings", bindings()},
                {"push_constants", pushConstants()}};
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
                {"window", vec(sweep.window)},
                {"phase_count", vec(sweep.phaseCount)},
                {"phases", phases}};
}

Json stageJson(const KernelPackage& package, const StagePlan& stage) {
    switch (stage.kind) {
    case Stage::Kind::Start: return Json{{"kind", "start"}, {"kernel", package.kernels.at(stage.startKernel).name}};
    case Stage::Kind::Grammar: {
        Json sweeps = Json::array();
        for (const SweepPlan& sweep : stage.grammar.sweeps)
            sweeps.push_back(sweepJson(package, sweep));
        return Json{{"kind", "grammar"},
                    {"grammar", stage.grammar.name},
                    {"iterations", stage.grammar.iterations},
                    {"sweeps", sweeps}};
    }
    case Stage::Kind::Field: {
        // Each box: [min, max] where the DAG is evaluated, [min, max, value] where the field is
        // that constant, [min, max, value, "unchanged"] where it is not dispatched at all.
        Json boxes = Json::array();
        for (const FieldBox& box : stage.fieldBoxes) {
            Json entry = Json::array({{box.min.x, box.min.y, box.min.z}, {box.max.x, box.max.y, box.max.z}});
            if (box.constant) entry.push_back(box.value);
            if (box.unchanged) entry.push_back("unchanged");
            boxes.push_back(entry);
        }
        Json field{{"kind", "field"},
                   {"field", stage.fieldName},
                   {"mode", ir::fieldModeName(stage.fieldMode)},
                   {"kernel", package.kernels.at(stage.fieldKernel).name},
                   {"boxes", boxes}};
        // The material id the stage writes where the field wins; absent: materials untouched.
        if (stage.fieldMaterial) field["material"] = *stage.fieldMaterial;
        return field;
    }
    }
    throw InternalError("unknown stage kind");
}

std::string spirvBytes(const std::vector<uint32_t>& words) {
    std::string bytes;
    bytes.reserve(words.size() * 4);
    for (uint32_t w : words)
        for (int shift = 0; shift < 32; shift += 8)
            bytes.push_back(char((w >> shift) & 0xffu));
    return bytes;
}

} // namespace

std::string packageManifest(const KernelPackage& package, const std::string& sourceFile) {
    const World& w = package.world;
    Json kernels = Json::array();
    for (const Kernel& k : package.kernels)
        kernels.push_back(kernelJson(k));
    Json stages = Json::array();
    for (const StagePlan& stage : package.stages)
        stages.push_back(stageJson(package, stage));
    const Json manifest{
        {"voxc_version", VOXC_VERSION},
        {"source_file", sourceFile},
        {"world", Json{{"size", vec(w.size)}, {"origin", vec(w.origin)}, {"chunk", w.chunkSize}, {"seed", w.seed}}},
        {"uses_materials", package.usesMaterials},
        {"kernels", kernels},
        {"dispatch", Json{{"tile_ranges_kernel", kernelName(package, package.tileRangesKernel)}, {"stages", stages}}}};
    return manifest.dump(2) + "\n";
}

void writePackage(const KernelPackage& package, const std::string& dir, const std::string& sourceFile) {
    const std::filesystem::path root(dir);
    std::error_code error;
    std::filesystem::create_directories(root / "kernels", error);
    if (error) throw UserError("cannot create directory " + (root / "kernels").string() + ": " + error.message());
    for (const Kernel& k : package.kernels) {
        writeFileAtomically((root / glslPath(k)).string(), k.glsl);
        writeFileAtomically((root / spirvPath(k)).string(), spirvBytes(k.spirv));
    }
    writeFileAtomically((root / "manifest.json").string(), packageManifest(package, sourceFile));
}

} // namespace voxc::codegen

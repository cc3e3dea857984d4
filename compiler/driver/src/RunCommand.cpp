#include "Commands.h"
#include "Common.h"
#include "Console.h"
#include "EditsFile.h"
#include "NonFiniteReport.h"
#include "OutputPaths.h"
#include "PhaseTimes.h"
#include "RegionOption.h"
#include "SolveReport.h"
#include "StageDebug.h"

#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/codegen/CompileCache.h"
#include "voxc/stages/SolveCache.h"
#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/LodExport.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"
#include "voxc/mesh/SurfaceNets.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/vulkan/GpuCurves.h"
#include "voxc/vulkan/GpuErosion.h"
#include "voxc/vulkan/GpuMesher.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <optional>

namespace voxc::driver {

namespace {

struct RunOptions {
    std::string file;
    std::string meshPath;
    std::string voxelsPath;
    std::string materialsPath;
    std::string device = "auto";
    float iso = 0.5f;
    std::string mesher = "mc";
    std::string meshOn; // "device" or "host"; empty: a GPU for mc, else the host
    std::string solveOn; // "device" or "host"; empty: the device unless it is a CPU (lavapipe)
    bool validate = false;
    bool listDevices = false;
    bool noCache = false;
    bool timings = false;
    std::string region;
    std::string editsPath; // --edits: brushes replayed on the host after generation
    std::vector<int> lod;         // levels: one mesh each beside -o
    std::vector<float> lodLayout; // with --lod: -o is the mixed-level mesh around this point
    std::vector<std::string> dumps; // --dump [BLOCK.]CHANNEL=FILE.npy
    StageDebugOptions stages; // --after, --diff, --slice, --channel
    WorldOverrides overrides;
};

// The grid `program` (cut for --diff) computes on the device, read back and cropped to the region.
DenseGrid generateOnDevice(VulkanContext& context, Program program, const std::string& region) {
    const RegionRun run = planRegionRun(std::move(program), region);
    const KernelPackage package = compileProgram(run.program, {});
    VulkanExecutor executor(context, package, {.readBack = true});
    const RunResult result = executor.run();
    return run.crop(result.grid.toDense());
}

void run(const RunOptions& options) {
    if (options.listDevices) {
        std::cout << formatDeviceList(VulkanContext::listDevices());
        return;
    }
    if (options.file.empty()) throw UserError("run: a .vox file is required");
    const std::vector<SolveDump> dumps = parseSolveDumps(options.dumps);
    if (!dumps.empty() && !options.region.empty())
        throw UserError("run: --dump writes a curves block's whole box, which a --region run does not keep; leave out --region");
    const bool printsGrid = !options.stages.diff.empty() || !options.stages.slice.empty();
    if (options.meshPath.empty() && options.voxelsPath.empty() && options.materialsPath.empty() && dumps.empty() &&
        !printsGrid)
        throw UserError("run: nothing to write; give -o MESH.ply|.obj|.glb, --voxels FILE.npy, --materials FILE.npy, "
                        "--dump CHANNEL=FILE.npy, --slice AXIS=INDEX and/or --diff STAGE");
    if (!options.editsPath.empty() && (!options.stages.after.empty() || !options.stages.diff.empty()))
        throw UserError("run: --edits are replayed on the finished grid; leave them out with --after or --diff");
    if (!options.meshPath.empty()) requireExtension(options.meshPath, {".ply", ".obj", ".glb"}, "mesh file");
    if (!std::isfinite(options.iso)) throw UserError(fmt::format("--iso {}: the surface level must be a finite number", options.iso));
    if (options.meshOn == "device" && !options.region.empty())
        throw UserError("run: --mesh-on device meshes the device's whole grid; a --region is meshed on the host");
    if (options.meshOn == "device" && !options.editsPath.empty())
        throw UserError("run: --mesh-on device meshes the device's grid; with --edits the edited grid is meshed on the host");
    if (options.meshOn == "device" && options.mesher != "mc")
        throw UserError("run: --mesh-on device: only marching cubes (--mesher mc) runs on the device; surface nets runs on the host");
    if (!options.lod.empty() && (options.meshPath.empty() || options.mesher != "mc" || options.meshOn == "device"))
        throw UserError("run: --lod meshes marching cubes on the host into files named after -o; give -o, and no "
                        "--mesher surface-nets or --mesh-on device");
    if (!options.lodLayout.empty() && options.lod.empty()) throw UserError("run: --lod-layout X,Y,Z needs --lod LEVELS");
    if (!options.voxelsPath.empty()) requireExtension(options.voxelsPath, {".npy"}, "voxel file");
    if (!options.materialsPath.empty()) requireExtension(options.materialsPath, {".npy"}, "material file");
    const std::string libraryPath = options.meshPath.ends_with(".obj") ? objMaterialLibraryPath(options.meshPath) : "";
    const RolePath inputs[] = {{"the input", options.file}, {"--edits", options.editsPath}};
    std::vector<RolePath> outputs = dumpOutputs(dumps);
    outputs.insert(outputs.begin(), {{"-o", options.meshPath},
                                     {"the material library of -o", libraryPath},
                                     {"--voxels", options.voxelsPath},
                                     {"--materials", options.materialsPath}});
    refuseClashingPaths(inputs, outputs);

    // Kernels compiled by earlier runs (SPIR-V, and the device's pipeline cache) are reused.
    const std::optional<std::filesystem::path> cache = options.noCache ? std::nullopt : codegen::defaultCacheDirectory();
    codegen::setCompileCacheDirectory(cache);
    PhaseTimes times;
    const auto since = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    double deviceMs = 0.0; // the device may be opened inside the solve (multigrid, erosion) or after it

    // Curves and terrain blocks are solved before the plan: their multigrid and erosion steps run on
    // the device, made then, unless it is a CPU device, where the host's loops are faster
    // (docs/curves.md, "What runs where").
    std::optional<VulkanContext> device;
    const auto openDevice = [&]() -> VulkanContext& {
        if (device) return *device;
        const auto start = std::chrono::steady_clock::now();
        device.emplace(ContextOptions{.device = options.device,
                                      .validation = options.validate,
                                      .pipelineCacheDirectory = cache ? cache->string() : ""});
        deviceMs = since(start);
        return *device;
    };
    WorldOverrides overrides = options.overrides;
    overrides.keepSolveChannels = !dumps.empty();
    std::string curvesDevice; // the device's name once a curves pass ran there
    if (options.solveOn != "host")
        overrides.curvesSolver = vulkanCurvesSolvers([&]() -> VulkanContext* {
            VulkanContext& solver = openDevice();
            if (options.solveOn.empty() && solver.device().type == DeviceType::Cpu) return nullptr;
            curvesDevice = solver.device().name;
            return &solver;
        });
    std::string erosionDevice; // the device's name once erosion steps ran there
    if (options.solveOn != "host")
        overrides.erosionRunner = [&](terrain::ErosionGrid& grid, const terrain::ErosionParams& params, int32_t level,
                                      uint32_t firstStep, uint32_t steps, bool drain) {
            VulkanContext& solver = openDevice();
            if (options.solveOn.empty() && solver.device().type == DeviceType::Cpu)
                return terrain::runErosionSteps(grid, params, level, firstStep, steps, drain);
            erosionDevice = solver.device().name;
            vulkanErosionRunner(solver)(grid, params, level, firstStep, steps, drain);
        };
    const auto checkStart = std::chrono::steady_clock::now();
    Program checked = loadProgram(options.file, withRegion(overrides, options.region));
    times.add("check", since(checkStart), "parse, check");
    const auto solveStart = std::chrono::steady_clock::now();
    const stages::SolveCacheCounts solvesBefore = stages::solveCacheCounts();
    stages::solveBlocks(checked, {overrides.curvesSolver, overrides.keepSolveChannels, overrides.erosionRunner});
    const stages::SolveCacheCounts solvesAfter = stages::solveCacheCounts();
    times.add("solve", since(solveStart) - deviceMs,
              fmt::format("curves and terrain blocks: {} solved, {} from the cache{}", solvesAfter.solved - solvesBefore.solved,
                          solvesAfter.hits - solvesBefore.hits, cache ? "" : " (--no-cache)"));
    const std::optional<StageCut> cut = selectStage(checked, options.stages);
    // --diff compares with the pipeline cut before the stage (all air and `none` before the first).
    std::optional<Program> before;
    if (cut && cut->diff && cut->stage > 0) before = throughStage(checked, cut->stage - 1);
    if (cut) checked = throughStage(std::move(checked), cut->stage);
    const RegionRun run = planRegionRun(std::move(checked), options.region);
    const Program& program = run.program;
    const std::vector<Brush> edits =
        options.editsPath.empty() ? std::vector<Brush>{} : loadEdits(options.editsPath, program);
    const codegen::CompileCacheCounts spirvBefore = codegen::compileCacheCounts();
    const KernelPackage package = times.time("lower+glsl", [&] { return compileProgram(program, {}); });
    const codegen::CompileCacheCounts spirvAfter = codegen::compileCacheCounts();
    times.split("lower+glsl", "spirv",
                spirvAfter.compileMs + spirvAfter.cacheMs - spirvBefore.compileMs - spirvBefore.cacheMs,
                fmt::format("{} kernels: {} from the cache, {} compiled{}", package.kernels.size(),
                            spirvAfter.hits - spirvBefore.hits, spirvAfter.compiled - spirvBefore.compiled,
                            cache ? "" : " (--no-cache)"));
    status() << formatSolveReport(program, false, curvesDevice);
    if (!erosionDevice.empty()) status() << fmt::format("terrain erosion steps ran on {}\n", erosionDevice);
    VulkanContext& context = openDevice();
    times.add("device", deviceMs, "instance, device, pipeline cache");
    // Without shaderFloat64 the default falls back to the host mesher (the same mesh, bit for bit);
    // asking for the device explicitly is then GpuMarchingCubes' error. On a CPU device (lavapipe)
    // the host mesher, which visits only the cells the surface crosses, is the faster of the two
    // on the same cores (docs/performance.md, "Meshing"), so it is the default there.
    const bool marchingCubes = options.mesher == "mc";
    const bool deviceCanMesh = context.hasShaderFloat64();
    const bool deviceIsCpu = context.device().type == DeviceType::Cpu;
    const bool meshOnDevice =
        marchingCubes && options.lod.empty() && !options.meshPath.empty() && !run.region && edits.empty() &&
        (options.meshOn == "device" || (options.meshOn.empty() && deviceCanMesh && !deviceIsCpu));
    // The grid comes back to the host only for what reads it there: a region's crop, edits, the
    // .npy files, material counts, the LOD meshes and the host meshers.
    const bool hostNeedsGrid = !meshOnDevice || !options.voxelsPath.empty() || !options.materialsPath.empty() ||
                               program.usesMaterials() || printsGrid;
    VulkanExecutor executor(context, package, {.readBack = hostNeedsGrid});
    times.add("pipelines", executor.setupMs(), "shader modules, pipelines, buffers");
    const RunResult result = times.time("generate", [&] { return executor.run(); });
    // A region's voxels, without its halo, mesh on the host; so does a grid with edits (EditsFile.h).
    std::optional<ChunkedGrid> cropped = run.region || !edits.empty()
                                             ? std::optional(run.region ? run.crop(result.grid) : result.grid)
                                             : std::nullopt;
    if (!edits.empty()) status() << describeEdits(edits.size(), applyEdits(*cropped, edits));
    const ChunkedGrid& voxels = cropped ? *cropped : result.grid;
    std::cerr << run.describe();
    status() << fmt::format("device: {} ({})\n", context.device().name, deviceTypeName(context.device().type));
    status() << fmt::format("grid {}x{}x{}, chunk {}, seed {}: {} dispatches, {:.1f} ms on device\n",
                             program.world.size.x, program.world.size.y, program.world.size.z,
                             program.world.chunkSize, program.world.seed, result.dispatches,
                             result.timings.executeMs);
    std::vector<SourceLoc> stageLocs;
    for (const StagePlan& stage : package.stages) stageLocs.push_back(stage.loc);
    std::cerr << formatNonFiniteWarnings(program, options.file, stageLocs, result.nonFinite);
    if (result.skip.enabled && result.skip.tilePhases > 0)
        status() << fmt::format("ran sweeps on {} of {} ({:.1f}%) {}^3-voxel tile-phases; the rest provably could not match\n",
                                 result.skip.activeTilePhases, result.skip.tilePhases,
                                 100.0 * double(result.skip.activeTilePhases) / double(result.skip.tilePhases),
                                 result.skip.tileSize);

    // Every file is written in full before any of them replaces what the user had.
    OutputFiles files;
    writeSolveDumps(files, program, dumps);
    if (cut) std::cout << describeCut(program, *cut);
    if (!options.voxelsPath.empty() || !options.materialsPath.empty() || program.usesMaterials() || printsGrid) {
        const DenseGrid dense = voxels.toDense();
        if (cut && cut->diff) {
            const DenseGrid previous =
                before ? times.time("diff", [&] { return generateOnDevice(context, std::move(*before), options.region); })
                       : DenseGrid(dense.size());
            std::cout << reportStageDiff(program, options.stages, previous, dense, options.iso);
        } else {
            std::cout << renderChosenSlice(program, options.stages, dense, options.iso);
        }
        if (program.usesMaterials()) status() << formatMaterialCounts(program, dense, options.iso);
        times.time("write", [&] { writeGridFiles(files, options.voxelsPath, options.materialsPath, dense); });
    }
    std::string meshReport;
    if (!options.lod.empty()) {
        const std::optional<glm::vec3> centre =
            options.lodLayout.empty() ? std::nullopt : std::optional(glm::vec3(options.lodLayout[0], options.lodLayout[1], options.lodLayout[2]));
        meshReport = times.time("mesh", [&] {
            return writeLodMeshes(files, voxels, {options.lod, centre, options.iso}, options.meshPath, program.materials);
        });
    } else if (!options.meshPath.empty()) {
        MeshStats stats;
        if (marchingCubes && options.meshOn.empty() && !deviceCanMesh && !deviceIsCpu && !run.region && edits.empty())
            std::cerr << fmt::format("voxc: note: the device '{}' has no shaderFloat64; marching cubes runs on the host\n",
                                     context.device().name);
        const MeshOptions meshOptions{.iso = options.iso};
        const Mesh mesh = times.time("mesh", [&] {
            return meshOnDevice    ? GpuMarchingCubes(executor).mesh(meshOptions, &stats)
                   : marchingCubes ? meshMarchingCubes(voxels, meshOptions, &stats)
                                   : meshSurfaceNets(voxels, meshOptions, &stats);
        });
        // Both meshers promise a closed mesh of finite vertices, marching cubes a manifold one too;
        // naive surface nets may join four faces at a saddle of the field (reported, not an error).
        if (stats.normalsMs > 0.0) times.split("mesh", "normals", stats.normalsMs, "vertex normals oriented to their triangles");
        const MeshQuality quality = times.time("quality", [&] { return measureMeshQuality(mesh); });
        if (quality.boundaryEdges != 0 || quality.nonFiniteVertices != 0 || quality.misorientedEdges != 0 ||
            (marchingCubes && !quality.manifold()))
            throw InternalError("the " + options.mesher + " mesh is broken: " + describeMeshQuality(quality));
        // A .glb is encoded whole (vertex-cache order, then the bytes) before it is written, so the
        // two show apart; PLY and OBJ stream their text or records into the file as they go.
        if (options.meshPath.ends_with(".glb")) { // requireExtension: the ending as written
            const std::string glb = times.time("encode", [&] { return encodeGlb(mesh, program.materials); });
            times.time("write", [&] { files.add(options.meshPath, glb); });
        } else {
            times.time("write", [&] { writeMesh(files, options.meshPath, mesh, program.materials); });
        }
        if (mesh.triangles.empty())
            std::cerr << fmt::format("voxc: warning: the mesh is empty: every voxel is on the same side of --iso {}\n", options.iso);
        meshReport = fmt::format("wrote {} ({}): {}; {}; skipped {} of {} chunks with no surface\n", options.meshPath,
                                 meshOnDevice ? "marching cubes on the device" : marchingCubes ? "marching cubes" : "surface nets",
                                 describeMeshQuality(quality),
                                 quality.nonManifoldEdges == 0 ? "watertight" : "closed, not manifold",
                                 stats.skippedChunks, stats.chunks);
    }
    times.time("write", [&] { files.commit(); });
    reportWritten({options.voxelsPath, options.materialsPath});
    for (const SolveDump& dump : dumps) reportWritten({dump.path});
    status() << meshReport;
    if (options.validate) {
        const std::vector<ValidationMessage> messages = context.validationMessages();
        std::cerr << fmt::format("validation layer: {} message{}\n", messages.size(), messages.size() == 1 ? "" : "s");
        for (const ValidationMessage& message : messages)
            std::cerr << "  " << (message.error ? "error: " : "warning: ") << message.text << "\n";
        if (!messages.empty()) throw InternalError("the Vulkan validation layer reported problems");
    }
    if (options.timings) std::cerr << times.format();
}

} // namespace

void addRunCommand(CLI::App& app) {
    auto options = std::make_shared<RunOptions>();
    CLI::App* command =
        app.add_subcommand("run", "Compile a .vox file, run it with Vulkan, mesh the result and export it "
                                  "(with material names and colours)");
    command->add_option("file", options->file, "The .vox file");
    command->add_option("-o,--output", options->meshPath, "Mesh to write (.ply binary, .obj or .glb)");
    command->add_option("--voxels", options->voxelsPath, "Also write the densities as a NumPy .npy file (float32)");
    command->add_option("--materials", options->materialsPath, "Also write the material ids as a NumPy .npy file (uint8)");
    addDumpFlag(*command, options->dumps);
    addDeviceFlag(*command, options->device);
    command->add_option("--iso", options->iso, "Surface level for meshing (default 0.5)");
    command->add_option("--mesher", options->mesher, "mc (marching cubes, manifold; the default) or surface-nets")
        ->check(CLI::IsMember({"mc", "surface-nets"}));
    command->add_option("--mesh-on", options->meshOn,
                        "device (marching cubes on the Vulkan device, over its voxel buffer; the default for mc on a "
                        "GPU) or host (the CPU mesher; the default on a CPU device such as lavapipe, and always for "
                        "surface-nets)")
        ->check(CLI::IsMember({"device", "host"}));
    command->add_option("--solve-on", options->solveOn,
                        "device or host: where curves blocks run their multigrid solves and terrain blocks their "
                        "erosion steps (the same values bit for bit on lavapipe; default: the device unless it is a "
                        "CPU device such as lavapipe)")
        ->check(CLI::IsMember({"device", "host"}));
    command->add_option("--lod", options->lod,
                        "LEVELS, e.g. 0,1,2: write one marching-cubes mesh per level beside -o (x.lod1.glb), "
                        "level k from every 2^k-th voxel")
        ->delimiter(',');
    command->add_option("--lod-layout", options->lodLayout,
                        "X,Y,Z (with --lod): also write -o as one mesh of mixed levels, finer near the world point X,Y,Z, "
                        "joined by transition cells")
        ->delimiter(',')
        ->expected(3);
    command->add_flag("--validate", options->validate, "Enable the Khronos validation layer; fail on any message");
    command->add_flag("--list-devices", options->listDevices, "List Vulkan devices and exit");
    command->add_flag("--no-cache", options->noCache,
                      "Neither read nor write the compile cache (SPIR-V by content, the device's pipeline cache) in "
                      "$VOXC_CACHE_DIR, else $XDG_CACHE_HOME/voxc, else ~/.cache/voxc");
    command->add_flag("--timings", options->timings,
                      "Print wall time per phase: check, solve, lower+glsl, spirv, device, pipelines, generate, mesh, write");
    addStageDebugFlags(*command, options->stages);
    addRegionFlag(*command, options->region);
    addEditsFlag(*command, options->editsPath);
    addWorldOverrideFlags(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] { run(*options); });
}

} // namespace voxc::driver

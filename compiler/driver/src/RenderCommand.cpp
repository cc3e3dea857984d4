// `voxc render`: a picture of a program's mesh (or of a mesh file) without a window, drawn by
// MeshRenderer on the device that generated it.
#include "Commands.h"
#include "Common.h"
#include "Console.h"
#include "EditsFile.h"
#include "OutputPaths.h"
#include "RegionOption.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/explore/Png.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/render/CutAway.h"
#include "voxc/render/Lighting.h"
#include "voxc/render/MeshRenderer.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/vulkan/GpuMesher.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <optional>

namespace voxc::driver {

namespace {

constexpr glm::vec3 kWireframeColour{0.05f, 0.05f, 0.05f};
constexpr glm::vec3 kChunkBorderColour{0.9f, 0.15f, 0.1f};

struct RenderOptions {
    std::string file;
    std::string output;
    std::string editsPath;
    std::string camera = "iso";
    std::string size = "1280x720";
    std::string device = "auto";
    std::string cut;
    std::string region;
    float iso = 0.5f;
    bool noOcclusion = false;
    bool noShadows = false;
    bool wireframe = false;
    bool chunkBorders = false;
    bool validate = false;
    WorldOverrides overrides;
};

// What is drawn: the mesh, its materials, and the grid's chunks and voxels when it came from a
// program (the voxels light the mesh: voxc/render/Lighting.h).
struct Scene {
    Mesh mesh;
    std::vector<Material> materials;
    std::optional<ChunkLayout> chunks;
    std::optional<DenseGrid> voxels;
    rendering::Bounds worldBox; // the grid's voxel box, or the mesh's bounds for a mesh file
};

Scene runProgram(VulkanContext& context, const RenderOptions& options) {
    const RegionRun run =
        planRegionRun(loadProgram(options.file, withRegion(options.overrides, options.region)), options.region);
    const Program& program = run.program;
    VulkanExecutor executor(context, compileProgram(program, {}));
    RunResult result = executor.run();
    status() << fmt::format("device: {} ({}); grid {}x{}x{}, {:.1f} ms on device\n", context.device().name,
                             deviceTypeName(context.device().type), program.world.size.x, program.world.size.y,
                             program.world.size.z, result.timings.executeMs);
    status() << run.describe();
    ChunkedGrid grid = run.region ? run.crop(result.grid) : std::move(result.grid);
    const std::vector<Brush> edits =
        options.editsPath.empty() ? std::vector<Brush>{} : loadEdits(options.editsPath, program);
    if (!edits.empty()) status() << describeEdits(edits.size(), applyEdits(grid, edits));
    if (!options.cut.empty())
        status() << fmt::format("cut away {} voxels ({})\n",
                                 rendering::applyCutAway(grid, rendering::parseCutAway(options.cut)), options.cut);
    // The device's marching cubes and the host's give the same mesh bit for bit (`voxc run`); a
    // region, an edited or a cut grid is meshed on the host, as `voxc run` does.
    const MeshOptions meshOptions{.iso = options.iso};
    const bool meshOnDevice = context.hasShaderFloat64() && !run.region && edits.empty() && options.cut.empty();
    Scene scene{meshOnDevice ? GpuMarchingCubes(executor).mesh(meshOptions) : meshMarchingCubes(grid, meshOptions),
                program.materials, grid.layout(), {}, {}};
    if (!options.noOcclusion || !options.noShadows) scene.voxels = grid.toDense();
    const ChunkLayout& layout = grid.layout();
    scene.worldBox = {glm::vec3(layout.gridOrigin), glm::vec3(layout.gridOrigin + layout.gridSize - 1)};
    return scene;
}

void renderFile(const RenderOptions& options) {
    if (options.file.empty()) throw UserError("render: a .vox file (or a .ply, .obj, .glb or .gltf mesh) is required");
    if (options.output.empty()) throw UserError("render: nothing to write; give -o PICTURE.png");
    requireExtension(options.output, {".png"}, "picture");
    if (!std::isfinite(options.iso)) throw UserError(fmt::format("--iso {}: the surface level must be a finite number", options.iso));
    std::string extension = std::filesystem::path(options.file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    // Every mesh format voxc writes is drawn as a mesh (readMesh), never parsed as a program.
    const bool meshFile = extension == ".ply" || extension == ".obj" || extension == ".glb" || extension == ".gltf";
    if (meshFile && options.chunkBorders) throw UserError("render: --chunk-borders needs a .vox file; a mesh file has no chunks");
    const rendering::ImageSize size = rendering::parseImageSize(options.size);
    const float aspect = float(size.width) / float(size.height);
    rendering::parseCamera(options.camera, {}, aspect); // the spelling, before the run
    if (meshFile && !options.editsPath.empty()) throw UserError("render: --edits needs a .vox file; a mesh file has no grid");
    if (meshFile && !options.cut.empty()) throw UserError("render: --cut needs a .vox file; a mesh file has no grid");
    if (meshFile && !options.region.empty()) throw UserError("render: --region needs a .vox file; a mesh file has no world");
    if (!options.cut.empty()) rendering::parseCutAway(options.cut); // the spelling, before the run
    const RolePath inputs[] = {{"the input", options.file}, {"--edits", options.editsPath}};
    const RolePath outputs[] = {{"-o", options.output}};
    refuseClashingPaths(inputs, outputs);

    VulkanContext context(ContextOptions{.device = options.device, .validation = options.validate});
    Scene scene;
    if (meshFile) {
        scene.mesh = readMesh(options.file, &scene.materials); // the colours the file carries
        scene.worldBox = rendering::meshBounds(scene.mesh);
    } else {
        scene = runProgram(context, options);
    }
    // Presets frame the surface; with no surface, the grid's box.
    const rendering::Bounds frame = scene.mesh.positions.empty() ? scene.worldBox : rendering::meshBounds(scene.mesh);
    if (scene.mesh.triangles.empty()) std::cerr << "voxc: warning: the mesh is empty; the picture shows the background\n";
    rendering::LineSet lines;
    if (options.wireframe) lines = rendering::wireframeLines(scene.mesh, kWireframeColour);
    if (options.chunkBorders) {
        const rendering::LineSet borders = rendering::chunkBorderLines(*scene.chunks, kChunkBorderColour);
        lines.points.insert(lines.points.end(), borders.points.begin(), borders.points.end());
        lines.colours.insert(lines.colours.end(), borders.colours.begin(), borders.colours.end());
    }
    rendering::Bounds enclosed = frame;
    if (options.chunkBorders) enclosed = scene.worldBox; // the borders must fit between near and far
    enclosed.min = glm::min(enclosed.min, frame.min);
    enclosed.max = glm::max(enclosed.max, frame.max);
    const rendering::Camera camera = rendering::parseCamera(options.camera, enclosed, aspect);

    // A mesh file has no voxels to measure light in: it is drawn with plain shading.
    std::optional<rendering::VertexLight> light;
    if (scene.voxels)
        light = rendering::lightVertices(scene.mesh, *scene.voxels, scene.chunks->gridOrigin,
                                         {.ambientOcclusion = !options.noOcclusion,
                                          .shadows = !options.noShadows,
                                          .towardsLight = rendering::towardsLight(camera),
                                          .iso = options.iso});
    MeshRenderer renderer(context, size);
    renderer.setScene(scene.mesh, scene.materials, lines, light ? &*light : nullptr);
    const rendering::Picture picture = renderer.draw(camera);
    explore::Image image(int(picture.width), int(picture.height), {});
    image.rgb = picture.rgb;
    if (options.validate) {
        const std::vector<ValidationMessage> messages = context.validationMessages();
        std::cerr << fmt::format("validation layer: {} message{}\n", messages.size(), messages.size() == 1 ? "" : "s");
        for (const ValidationMessage& message : messages)
            std::cerr << "  " << (message.error ? "error: " : "warning: ") << message.text << "\n";
        if (!messages.empty()) throw InternalError("the Vulkan validation layer reported problems");
    }
    writeFileAtomically(options.output, explore::encodePng(image));
    status() << fmt::format("wrote {} ({}x{}, {} triangles, camera {})\n", options.output, size.width, size.height,
                             scene.mesh.triangles.size() / 3, options.camera);
}

} // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand(
        "render", "Run a .vox file (or read a mesh file), mesh it and draw a shaded picture offscreen with Vulkan");
    command->add_option("file", options->file, "The .vox file, or a mesh file: .ply, .obj (with its .mtl), .glb or .gltf, such as `voxc run` writes");
    command->add_option("-o,--output", options->output, "The picture to write (.png)");
    command->add_option("--camera", options->camera,
                        "iso (default), top, side, or X,Y,Z:TX,TY,TZ (eye and target in world voxels)");
    command->add_option("--size", options->size, "WIDTHxHEIGHT in pixels (default 1280x720)");
    addEditsFlag(*command, options->editsPath);
    addRegionFlag(*command, options->region);
    command->add_flag("--wireframe", options->wireframe, "Draw the mesh's edges over its faces");
    command->add_flag("--chunk-borders", options->chunkBorders, "Draw the boxes of the grid's chunks");
    command->add_option("--cut", options->cut,
                        "Remove rock before meshing so caves show: x>N, x<N (y, z likewise) or "
                        "MINX,MINY,MINZ:MAXX,MAXY,MAXZ (world voxels, max excluded)");
    command->add_flag("--no-ao", options->noOcclusion, "Plain ambient light, without occlusion measured in the voxels");
    command->add_flag("--no-shadows", options->noShadows, "No shadows of the directional light");
    addDeviceFlag(*command, options->device);
    command->add_option("--iso", options->iso, "Surface level for meshing (default 0.5)");
    command->add_flag("--validate", options->validate, "Enable the Khronos validation layer; fail on any message");
    addWorldOverrideFlags(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] { renderFile(*options); });
}

} // namespace voxc::driver

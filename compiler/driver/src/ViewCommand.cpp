// `voxc view`: the interactive viewer (voxc/viewer/Viewer.h), or a script of its actions run
// headless under a virtual display.
#include "Commands.h"
#include "Common.h"
#include "Console.h"
#include "EditsFile.h"

#include "voxc/codegen/CompileCache.h"
#include "voxc/core/Errors.h"
#include "voxc/render/Camera.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/viewer/Viewer.h"

#include <filesystem>
#include <fmt/format.h>

namespace voxc::driver {

namespace {

struct ViewCommandOptions {
    std::string file;
    std::string editsPath;
    std::string scriptPath;
    std::string screenshot;
    std::string camera = "iso";
    std::string size = "1280x720";
    std::string device = "auto";
    float iso = 0.5f;
    WorldOverrides overrides;
};

std::vector<viewer::Action> loadScript(const std::string& path) {
    Diagnostics diagnostics;
    const std::optional<SourceFile> source = loadSourceFile(path, diagnostics);
    std::vector<viewer::Action> actions;
    if (source && !reportIfNotText(*source, diagnostics)) actions = viewer::parseScript(*source, diagnostics);
    printDiagnostics(diagnostics.all(), source ? *source : SourceFile(path, ""));
    failOnErrors(path, diagnostics.all());
    if (actions.empty()) throw UserError(fmt::format("{}: the script has no actions", path));
    return actions;
}

void view(const ViewCommandOptions& options) {
    if (!options.screenshot.empty()) requireExtension(options.screenshot, {".png"}, "screenshot");
    viewer::ViewerOptions viewerOptions;
    viewerOptions.session = {options.file, options.overrides.seed, options.overrides.chunk, options.iso};
    viewerOptions.size = rendering::parseImageSize(options.size);
    rendering::parseCamera(options.camera, {}, 1.0f); // the spelling, before the window opens
    viewerOptions.camera = options.camera;
    // Kernels compiled before (SPIR-V, and the device's pipeline cache) are reused, across runs and
    // across reloads of the window: a slider recompiles only the kernels whose text it changed.
    const std::optional<std::filesystem::path> cache = codegen::defaultCacheDirectory();
    codegen::setCompileCacheDirectory(cache);
    viewerOptions.context = {.device = options.device, .pipelineCacheDirectory = cache ? cache->string() : ""};
    viewerOptions.editsPath = options.editsPath;
    viewerOptions.screenshot = options.screenshot;
    if (!options.scriptPath.empty()) {
        viewerOptions.scriptPath = options.scriptPath;
        viewerOptions.script = loadScript(options.scriptPath);
    }
    // An edits file that does not exist yet is where "save edits" will write.
    if (!options.editsPath.empty() && std::filesystem::exists(options.editsPath))
        viewerOptions.session.readEdits = [path = options.editsPath](const Program& program) {
            return loadEdits(path, program);
        };
    viewer::runViewer(viewerOptions);
}

} // namespace

void addViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "view", "Open a window on a .vox file's world: orbit, carve and add with a brush, sliders for its parameters, "
                "reloaded when the file is saved (or run a --script of actions headless)");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("--edits", options->editsPath,
                        "A JSON edits file replayed on the world first; \"save edits\" (Ctrl+S) writes there "
                        "(default FILE.vox.edits.json)");
    command->add_option("--script", options->scriptPath, "Run these actions (docs/viewer.md, Scripts) and exit");
    command->add_option("--screenshot", options->screenshot, "Write the 3D view as PNG when the script ends or the window closes");
    command->add_option("--camera", options->camera, "The first view: iso (default), top, side, or X,Y,Z:TX,TY,TZ");
    command->add_option("--size", options->size, "The window's WIDTHxHEIGHT in pixels (default 1280x720)");
    addDeviceFlag(*command, options->device);
    command->add_option("--iso", options->iso, "Surface level for meshing and picking (default 0.5)");
    addWorldOverrideFlags(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] { view(*options); });
}

} // namespace voxc::driver

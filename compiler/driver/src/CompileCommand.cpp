#include "Commands.h"
#include "Common.h"
#include "OutputPaths.h"

#include "voxc/codegen/PackageWriter.h"
#include "voxc/ir/Lower.h"
#include "voxc/stages/Pipeline.h"

#include <filesystem>
#include <iostream>

namespace voxc::driver {

namespace {

struct CompileCommandOptions {
    std::string file;
    std::string outputDir;
    bool dumpIr = false;
    WorldOverrides overrides;
};

} // namespace

void addCompileCommand(CLI::App& app) {
    auto options = std::make_shared<CompileCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "compile", "Compile a .vox file into a package: GLSL kernels, SPIR-V and manifest.json");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("-o,--output", options->outputDir, "Package directory to write")->required();
    command->add_flag("--dump-ir", options->dumpIr, "Print the IR after every compiler pass to stdout");
    addWorldOverrideFlags(*command, options->overrides);
    command->callback([options] {
        const RolePath inputs[] = {{"the input", options->file}};
        refuseInputsInside({"-o", options->outputDir}, inputs);
        std::string sourceText;
        const Program program = loadProgram(options->file, options->overrides, false, &sourceText);
        voxc::CompileOptions compileOptions;
        if (options->dumpIr) {
            compileOptions.afterPass = [](std::string_view pass, const ir::IrModule& module) {
                std::cout << "=== after " << pass << " ===\n" << ir::printIr(module) << "\n";
            };
        }
        const KernelPackage package = compileProgram(program, compileOptions);
        const codegen::PackageSource source{std::filesystem::path(options->file).filename().string(), sourceText};
        const codegen::PackageWrite written = codegen::writePackage(package, options->outputDir, source);
        if (written == codegen::PackageWrite::Unchanged)
            std::cerr << options->outputDir << " is up to date (" << package.kernels.size() << " kernels)\n";
        else
            std::cerr << "wrote " << package.kernels.size() << " kernels to " << options->outputDir << "\n";
    });
}

} // namespace voxc::driver

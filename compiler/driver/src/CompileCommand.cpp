#include "Commands.h"
#include "Common.h"
#include "Console.h"
#include "Depfile.h"
#include "OutputPaths.h"

#include "voxc/check/LoadPackage.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/Lower.h"
#include "voxc/stages/Pipeline.h"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

struct CompileCommandOptions {
    std::string file;
    std::string outputDir;
    bool dumpIr = false;
    WorldOverrides overrides;
    DepfileOptions depfile;
};

// The package directory is replaced as a whole, and a package holds only voxc's own files.
void refuseDepfileInside(const std::string& packageDir, const std::string& depfile) {
    namespace fs = std::filesystem;
    const fs::path root = fs::weakly_canonical(fs::absolute(packageDir)) / "";
    const fs::path file = fs::weakly_canonical(fs::absolute(depfile));
    if (file.string().starts_with(root.string()) || file == root.parent_path())
        throw UserError(fmt::format("-MF '{}' is inside the package directory -o '{}', which voxc replaces as a whole",
                                    depfile, packageDir));
}

void compile(const CompileCommandOptions& options) {
    const bool writeDepfile = options.depfile.write || !options.depfile.path.empty() || !options.depfile.target.empty();
    const std::string depfile = writeDepfile ? depfilePath(options.depfile, options.outputDir) : "";
    const RolePath inputs[] = {{"the input", options.file}};
    refuseInputsInside({"-o", options.outputDir}, inputs);
    if (writeDepfile) {
        const RolePath outputs[] = {{"-MF", depfile}};
        refuseClashingPaths(inputs, outputs);
        refuseDepfileInside(options.outputDir, depfile);
    }

    std::string sourceText;
    std::vector<CheckedLsystem> lsystems;
    const Program program = loadProgram(options.file, options.overrides, false, &sourceText, &lsystems);
    voxc::CompileOptions compileOptions;
    if (options.dumpIr) {
        compileOptions.afterPass = [](std::string_view pass, const ir::IrModule& module) {
            std::cout << "=== after " << pass << " ===\n" << ir::printIr(module) << "\n";
        };
    }
    const auto start = std::chrono::steady_clock::now();
    const KernelPackage package = compileProgram(program, compileOptions);
    const std::chrono::duration<double, std::milli> compileTime = std::chrono::steady_clock::now() - start;
    detail() << fmt::format("compiled {} kernels in {:.1f} ms\n", package.kernels.size(), compileTime.count());
    const codegen::PackageSource source = packageSource(options.file, sourceText, lsystems, program.inputs);
    const codegen::PackageWrite written = codegen::writePackage(package, options.outputDir, source);
    if (written == codegen::PackageWrite::Unchanged)
        status() << options.outputDir << " is up to date (" << package.kernels.size() << " kernels)\n";
    else
        status() << "wrote " << package.kernels.size() << " kernels to " << options.outputDir << "\n";
    if (writeDepfile) {
        // Written after the package, so a build that reads it knows the package is whole.
        const std::vector<std::string> depends = packageInputs(options.file, lsystems, program.inputs);
        writeFileAtomically(depfile, formatDepfile(depfileTarget(options.depfile, options.outputDir), depends));
        status() << fmt::format("wrote {} ({} input{})\n", depfile, depends.size(), depends.size() == 1 ? "" : "s");
    }
}

} // namespace

void addCompileCommand(CLI::App& app) {
    auto options = std::make_shared<CompileCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "compile", "Compile a .vox file into a package: GLSL kernels, SPIR-V and manifest.json");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("-o,--output", options->outputDir, "Package directory to write")->required();
    command->add_flag("--dump-ir", options->dumpIr, "Print the IR after every compiler pass to stdout");
    addWorldOverrideFlags(*command, options->overrides);
    addDepfileFlags(*command, options->depfile);
    addConsoleFlags(*command);
    command->callback([options] { compile(*options); });
}

} // namespace voxc::driver

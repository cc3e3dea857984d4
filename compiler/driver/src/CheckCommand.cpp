#include "Commands.h"
#include "Common.h"
#include "Console.h"
#include "RegionOption.h"

#include <iostream>

namespace voxc::driver {

namespace {

struct CheckOptions {
    std::string file;
    bool warningsAsErrors = false;
    bool explainHalo = false;
    std::string region;
    WorldOverrides overrides; // --max-work only
};

} // namespace

void addCheckCommand(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* command = app.add_subcommand("check", "Parse and type-check a .vox file; print diagnostics only");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_flag("--werror", options->warningsAsErrors, "Treat warnings as errors");
    command->add_flag("--explain-halo", options->explainHalo,
                      "Print each stage's dependency radius and the halo a --region is grown by");
    addRegionFlag(*command, options->region);
    addMaxWorkFlag(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] {
        // With --region the world may exceed one grid: the check bounds the region's instead.
        const Program program =
            loadProgram(options->file, withRegion(options->overrides, options->region), options->warningsAsErrors);
        if (!options->region.empty()) stages::parseRegion(options->region, program.world); // inside the world
        if (options->explainHalo) std::cout << explainHalo(program, options->file);
        status() << options->file << ": ok\n";
    });
}

} // namespace voxc::driver

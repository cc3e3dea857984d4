#include "Commands.h"
#include "Common.h"

#include <iostream>

namespace voxc::driver {

namespace {

struct CheckOptions {
    std::string file;
    bool warningsAsErrors = false;
    WorldOverrides overrides; // --max-work only
};

} // namespace

void addCheckCommand(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* command = app.add_subcommand("check", "Parse and type-check a .vox file; print diagnostics only");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_flag("--werror", options->warningsAsErrors, "Treat warnings as errors");
    addMaxWorkFlag(*command, options->overrides);
    command->callback([options] {
        loadProgram(options->file, options->overrides, options->warningsAsErrors);
        std::cerr << options->file << ": ok\n";
    });
}

} // namespace voxc::driver

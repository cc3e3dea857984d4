#pragma once
// `voxc compile -MD [-MF FILE] [-MT TARGET]`: a make/ninja depfile naming every file the package
// was built from (the .vox, the rule files its lsystem blocks import and the files its heightmap
// and mesh blocks read), so a build system
// recompiles when any of them changes (docs/cli.md, "Build pipelines").
#include "voxc/check/Check.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace voxc::driver {

struct DepfileOptions {
    bool write = false;  // -MD (implied by -MF and -MT)
    std::string path;    // -MF; default: the package directory's path + ".d"
    std::string target;  // -MT; default: PKG_DIR/manifest.json
};

// -MD, -MF FILE and -MT TARGET.
void addDepfileFlags(CLI::App& command, DepfileOptions& options);

// gcc spells these with one dash (`-MD`), which CLI11 reads as bundled short flags: rewrites
// them to their long forms (`--MD`) before parsing. Other arguments are kept as they are.
std::vector<std::string> spellDepfileFlagsLong(int argc, char** argv);

// The files the package of `file` was built from: the .vox, then each imported rule file and
// each file a heightmap or mesh block reads, once, as the checker opened them.
std::vector<std::string> packageInputs(const std::string& file, const std::vector<CheckedLsystem>& lsystems,
                                       const std::vector<InputFile>& files = {});

// "TARGET: INPUT INPUT ...\n" in make syntax (spaces, '#' and '$' escaped); UserError for a
// path with a newline, which no depfile can hold.
std::string formatDepfile(const std::string& target, const std::vector<std::string>& inputs);

// Where -MD writes for the package directory `packageDir`, and the target it names there.
std::string depfilePath(const DepfileOptions& options, const std::string& packageDir);
std::string depfileTarget(const DepfileOptions& options, const std::string& packageDir);

} // namespace voxc::driver

#pragma once
// A package directory that `voxc compile` wrote, loaded back as the program and plan it holds
// (libvoxc's voxc_package_load; docs/embedding.md): the package's copy of the .vox, its rule
// files and its heightmap and mesh files is checked again with the seed and chunk size it was compiled with, and compiled with the
// package's SPIR-V (glslang never runs), and every file of the package must be what that writes.
#include "voxc/check/Check.h"
#include "voxc/codegen/KernelPackage.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/program/Program.h"

#include <string>
#include <vector>

namespace voxc {

// What `voxc compile` keeps of the checked file at `path` in its package: the file name, the
// text, each rule file its lsystem blocks import, then each file its heightmap and mesh blocks
// read (each once, in declaration order).
codegen::PackageSource packageSource(const std::string& path, const std::string& text,
                                     const std::vector<CheckedLsystem>& lsystems,
                                     const std::vector<InputFile>& inputs = {});

struct LoadedPackage {
    Program program;
    KernelPackage package;
};

// UserError "cannot load package 'DIR': ..." saying why (codegen::readPackage's reasons; the
// sources do not check; a file differs from what they compile to), so a corrupt, foreign or
// other version's package is never run.
LoadedPackage loadPackage(const std::string& directory);

} // namespace voxc

#pragma once
// Reading back a package directory that writePackage wrote (libvoxc's voxc_package_load): its
// files, checked against the manifest's hashes, and the SPIR-V it holds, which
// compileComputeShader then takes instead of running glslang. The plan itself is not parsed from
// the manifest: the loader checks and compiles the package's copy of the sources again (with
// the package's SPIR-V) and verifyRebuiltPackage compares every file with what that gives.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/codegen/PackageWriter.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace voxc::codegen {

// A kernel as a package holds it: the GLSL it was compiled from and its SPIR-V.
struct PackagedKernel {
    std::string glsl;
    std::vector<uint32_t> spirv;
};

struct PackageContents {
    std::string directory;                     // as given, for messages
    std::map<std::string, std::string> files;  // every file: path relative to the package -> bytes
    PackageSource source;                      // the .vox and its rule files, from sources/
    uint32_t seed = 0;                         // world.seed: the file's, or `voxc compile --seed`'s
    int32_t chunkSize = 0;                     // world.chunk: the file's, or `--chunk`'s
    std::map<std::string, PackagedKernel, std::less<>> kernels; // by kernel name
};

// Reads the package at `dir`. UserError "cannot load package 'DIR': ..." when it is missing, not
// a directory, holds files voxc does not write, has no or an unreadable manifest, was written by
// another voxc version or without its sources, or a source or SPIR-V file does not match the
// manifest's SHA-256 (a corrupt package is never used).
PackageContents readPackage(const std::string& dir);

// After the package's sources were checked and compiled with its kernels (PackagedSpirvScope):
// UserError naming the first file of `contents` that differs from what `rebuilt` writes, so the
// plan a loader runs is exactly the one the manifest describes.
void verifyRebuiltPackage(const KernelPackage& rebuilt, const PackageContents& contents);

// While one lives on a thread, compileComputeShader on that thread returns the package's SPIR-V
// for a kernel of the same name and GLSL instead of compiling it, and throws UserError for any
// other kernel (the package is not what its sources compile to). Not nestable.
class PackagedSpirvScope {
public:
    explicit PackagedSpirvScope(const PackageContents& contents);
    ~PackagedSpirvScope();
    PackagedSpirvScope(const PackagedSpirvScope&) = delete;
    PackagedSpirvScope& operator=(const PackagedSpirvScope&) = delete;
};

} // namespace voxc::codegen

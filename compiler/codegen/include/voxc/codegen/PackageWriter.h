#pragma once
// Writes a KernelPackage as files: dir/manifest.json, dir/kernels/<name>.comp (GLSL) and
// dir/kernels/<name>.spv (SPIR-V words, little endian). Every file is written atomically.
#include "voxc/codegen/KernelPackage.h"

#include <string>

namespace voxc::codegen {

// KernelPackage does not record its source file, so the caller passes it for the manifest.
void writePackage(const KernelPackage& package, const std::string& dir, const std::string& sourceFile = {});

// The manifest text writePackage writes (JSON, keys in a fixed order, trailing newline).
std::string packageManifest(const KernelPackage& package, const std::string& sourceFile = {});

} // namespace voxc::codegen

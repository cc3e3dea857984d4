#pragma once
// The kernel of one pass of a SolveProgram built from GLSL (GpuMultigrid.cpp, GpuCurves.cpp,
// GpuErosion.cpp).
#include "voxc/codegen/KernelPackage.h"
#include "voxc/codegen/Spirv.h"

#include <string>

namespace voxc {

// `glsl` compiled to SPIR-V (InternalError when it does not compile), workgroups of `localSize`
// invocations along x.
inline Kernel solvePassKernel(std::string name, std::string origin, std::string glsl, uint32_t localSize) {
    Kernel k;
    k.spirv = codegen::compileComputeShader(name, glsl);
    k.name = std::move(name);
    k.origin = std::move(origin);
    k.glsl = std::move(glsl);
    k.localSize[0] = localSize, k.localSize[1] = 1, k.localSize[2] = 1;
    return k;
}

} // namespace voxc

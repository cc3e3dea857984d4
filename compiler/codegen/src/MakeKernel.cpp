#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Spirv.h"
#include "voxc/core/Errors.h"

namespace voxc::codegen {

namespace {

// Every kernel of a package that uses materials is compiled with VOXC_MATERIALS, so
// common.glsl declares the material buffer (kBindingMaterials).
std::string withMaterials(std::string glsl) {
    const size_t lineEnd = glsl.find('\n');
    VOXC_ASSERT(glsl.starts_with("#version") && lineEnd != std::string::npos);
    return glsl.insert(lineEnd + 1, "#define VOXC_MATERIALS\n");
}

} // namespace

Kernel makeKernel(std::string name, std::string origin, const DispatchShape& shape, std::string glsl,
                  bool usesMaterials) {
    Kernel kernel;
    kernel.name = std::move(name);
    kernel.origin = std::move(origin);
    kernel.glsl = usesMaterials ? withMaterials(std::move(glsl)) : std::move(glsl);
    for (int a = 0; a < 3; ++a) {
        kernel.localSize[a] = shape.localSize[a];
        kernel.anchorsPerInvocation[a] = shape.anchorsPerInvocation[a];
    }
    kernel.spirv = compileComputeShader(kernel.name, kernel.glsl);
    kernel.bindings = spirvDescriptorBindings(kernel.spirv);
    return kernel;
}

} // namespace voxc::codegen

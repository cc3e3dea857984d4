#include "voxc/codegen/KernelSources.h"

#include <fmt/format.h>

namespace voxc::codegen {

std::string dispatchShapeGlsl(const DispatchShape& shape) {
    const uint32_t* l = shape.localSize;
    const uint32_t* a = shape.anchorsPerInvocation;
    return fmt::format("layout(local_size_x = {}, local_size_y = {}, local_size_z = {}) in;\n"
                       "// Each invocation handles this many consecutive anchors of its dispatch per axis\n"
                       "// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).\n"
                       "const ivec3 ANCHORS_PER_INVOCATION = ivec3({}, {}, {});\n",
                       l[0], l[1], l[2], a[0], a[1], a[2]);
}

} // namespace voxc::codegen

#include "KernelSources.h"
#include "Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"

#include <fmt/format.h>

namespace voxc::codegen {

std::string startKernelSource(const ir::IrModule& module, std::string_view sourceName) {
    std::string header = fmt::format("voxc generated kernel \"start\": the start state of {}.\n", sourceName);
    std::string shapes;
    if (module.start.empty()) {
        header += "The start block is empty: the grid starts as air.\n";
        shapes = "// No shapes: every voxel stays air.\n";
    } else {
        header += "Shapes in order; each overwrites the density where it is solid:\n";
    }
    for (const StartShape& shape : module.start) {
        const ShapeInfo& info = shapeInfo(shape.kind);
        const std::string where = fmt::format("{}:{}:{}", sourceName, shape.loc.line, shape.loc.column);
        header += fmt::format("  {} value {} ({})\n", info.name, glslFloat(shape.value), where);
        shapes += fmt::format("// {} ({})\n{{\n", info.name, where);
        shapes += prefixLines(info.glsl(shape), "    ") + "}\n";
    }
    return instantiateTemplate("start.glsl", {{"HEADER", prefixLines(header, "// ")}, {"SHAPES", shapes}});
}

} // namespace voxc::codegen

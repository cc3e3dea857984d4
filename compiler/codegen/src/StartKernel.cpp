#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::codegen {

DispatchShape startDispatchShape(const ir::IrModule& module) {
    // A workgroup of 8 x 8 columns; each invocation walks its whole column along y.
    return DispatchShape{{8, 1, 8}, {1, uint32_t(module.world.size.y), 1}};
}

std::string startKernelSource(const ir::IrModule& module, std::string_view sourceName) {
    std::string header = fmt::format("voxc generated kernel \"start\": the start state of {}.\n", sourceName);
    std::string columns, shapes;
    const bool writesMaterials =
        std::any_of(module.start.begin(), module.start.end(), [](const StartShape& s) { return s.material.has_value(); });
    if (module.start.empty()) {
        header += "The start block is empty: the grid starts as air.\n";
        shapes = "// No shapes: every voxel stays air.\n";
    } else {
        header += "Shapes in order; each overwrites the density where it is solid:\n";
    }
    for (size_t i = 0; i < module.start.size(); ++i) {
        const StartShape& shape = module.start[i];
        const ShapeInfo& info = shapeInfo(shape.kind);
        const std::string where = fmt::format("{}:{}:{}", sourceName, shape.loc.line, shape.loc.column);
        const std::string material = shape.material ? fmt::format(" material {}", *shape.material) : "";
        header += fmt::format("  {} value {}{} ({})\n", info.name, glslFloat(shape.value), material, where);
        shapes += fmt::format("// {} ({})\n{{\n", info.name, where);
        // The shape is tested at the file's grid-local voxel: the world place less the declared
        // grid's origin, the same for every region of the world (a region grid's own index is not),
        // so equal-sized tiles of a world share this kernel (docs/scale.md).
        const glm::ivec3 declaredOrigin = module.world.origin - module.world.localBase;
        shapes += declaredOrigin == glm::ivec3(0)
                      ? "    ivec3 local = world;\n"
                      : fmt::format("    ivec3 local = world - ivec3({}, {}, {});\n", declaredOrigin.x,
                                    declaredOrigin.y, declaredOrigin.z);
        if (info.columnGlsl) {
            columns += fmt::format("float column{} = {}; // {} ({})\n", i, info.columnGlsl(shape), info.name, where);
            shapes += fmt::format("    float column = column{};\n", i);
        }
        shapes += "    bool inside = false;\n" + prefixLines(info.glsl(shape), "    ");
        shapes += fmt::format("    if (inside) {{\n        density = {};\n", glslFloat(shape.value));
        if (shape.material) shapes += fmt::format("        material = {}u;\n", *shape.material);
        shapes += "    }\n}\n";
    }
    // Materials are stored only when a shape writes one: the run clears the buffer to none.
    shapes += writesMaterials ? "materials.material[address] = material;\n" : "";
    if (columns.empty()) columns = "// No shape has a per-column value.\n";
    return instantiateTemplate("start.glsl", {{"HEADER", prefixLines(header, "// ")},
                                              {"DISPATCH_SHAPE", dispatchShapeGlsl(startDispatchShape(module))},
                                              {"COLUMN_VALUES", columns},
                                              {"SHAPES", shapes}});
}

} // namespace voxc::codegen

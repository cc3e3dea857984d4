// The curves stage's combine, written as voxc::combineField computes it: the same comparisons,
// `1.0 - f` as one precise subtraction, ties keeping the grid's density.
#include "voxc/codegen/CurvesKernel.h"

#include "voxc/codegen/Template.h"

#include "voxc/ir/Ir.h"

#include <fmt/format.h>

namespace voxc::codegen {

namespace {

std::string combineGlsl(FieldMode mode, bool writesMaterials) {
    std::string wins;
    switch (mode) {
    case FieldMode::Set: wins = "bool wins = true;\nfloat result = f;\n"; break;
    case FieldMode::Union: wins = "bool wins = density < f;\nfloat result = wins ? f : density;\n"; break;
    case FieldMode::Subtract:
        wins = "precise float carved = 1.0 - f;\nbool wins = carved < density;\nfloat result = wins ? carved : density;\n";
        break;
    case FieldMode::Intersect: wins = "bool wins = f < density;\nfloat result = wins ? f : density;\n"; break;
    case FieldMode::Paint: break; // the checker rejects it: a curves stage carries its own materials
    }
    std::string code = fmt::format("// {}\nfloat density = voxels.density[address];\n{}voxels.density[address] = result;\n",
                                   ir::fieldModeName(mode), wins);
    if (writesMaterials)
        code += "if (wins && result >= 0.5) materials.material[address] = uint(solveTables.words[materialsAt + at]);\n";
    return code;
}

} // namespace

DispatchShape curvesDispatchShape(const ir::IrModule& module) { return startDispatchShape(module); }

std::string curvesKernelSource(const ir::IrModule& module, uint32_t table, FieldMode mode, bool writesMaterials,
                               std::string_view kernelName, std::string_view origin) {
    return instantiateTemplate(
        "curves.glsl",
        {{"HEADER", prefixLines(fmt::format("voxc generated kernel \"{}\": {}.\n", kernelName, origin), "// ")},
         {"DISPATCH_SHAPE", dispatchShapeGlsl(curvesDispatchShape(module))},
         {"TABLE", fmt::format("const int SOLVE_TABLE = {};", table)},
         {"COMBINE", combineGlsl(mode, writesMaterials)}});
}

} // namespace voxc::codegen

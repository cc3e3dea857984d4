// GLSL for a speleothem stage: the shared air-mask prepass (speleothem_mask.glsl) and one grow
// kernel per stage (speleothem_grow.glsl) with the stage's parameters as constants, written as
// the float literals the CPU uses (glslFloat round-trips every float).
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/codegen/KernelSources.h"

#include <fmt/format.h>

namespace voxc::codegen {

DispatchShape speleothemDispatchShape(const ir::IrModule& module) { return startDispatchShape(module); }

std::string speleothemMaskKernelSource(const ir::IrModule& module, std::string_view sourceName) {
    return instantiateTemplate(
        "speleothem_mask.glsl",
        {{"HEADER", prefixLines(fmt::format("voxc generated kernel \"speleothem_mask\" of {}: the air voxels before "
                                            "each speleothem stage.\n",
                                            sourceName),
                                "// ")},
         {"DISPATCH_SHAPE", dispatchShapeGlsl(speleothemDispatchShape(module))}});
}

std::string speleothemGrowKernelSource(const ir::IrModule& module, const SpeleothemStage& stage,
                                       std::optional<uint8_t> material, std::optional<uint32_t> clearanceSet,
                                       std::string_view kernelName, std::string_view sourceName) {
    const SpeleothemParams& p = stage.params;
    std::string parameters = fmt::format(
        "const int SPELEOTHEM_KIND = {};\n"
        "const float SPELEOTHEM_CLUSTER_FREQUENCY = {};\n"
        "const float SPELEOTHEM_CLUSTER_LOW = {};\n"
        "const float SPELEOTHEM_CLUSTER_HIGH = {};\n"
        "const float SPELEOTHEM_SPAWN_FREQUENCY = {};\n"
        "const float SPELEOTHEM_SPAWN_THRESHOLD = {};\n"
        "const float SPELEOTHEM_REACH_SCALE = {};\n"
        "const float SPELEOTHEM_GROWTH = {};\n"
        "const int SPELEOTHEM_TAPER = {};\n"
        "const int SPELEOTHEM_MIN_GAP = {};\n"
        "const int SPELEOTHEM_MAX_GAP = {};\n"
        "const uint SPELEOTHEM_MATERIAL = {}u;\n",
        int(p.kind), glslFloat(p.clusterFrequency), glslFloat(p.clusterLow), glslFloat(p.clusterHigh),
        glslFloat(p.spawnFrequency), glslFloat(p.spawnThreshold), glslFloat(speleothemReachScale(p)), glslFloat(p.growth), p.taper, p.minGap, p.maxGap,
        material.value_or(0));
    if (clearanceSet) {
        // pointSetClearance: the capped segment distance below the clearance (header word 12).
        parameters += fmt::format("#include \"lsystem_carve.glsl\"\n"
                                  "bool speleothemProtected(ivec3 world) {{\n"
                                  "    int set = {};\n"
                                  "    float clearance = pointSetFloat(pointSets.words[set] + 12);\n"
                                  "    return pointSetDistances(set, vec3(world)).y < clearance;\n"
                                  "}}\n",
                                  *clearanceSet);
    } else {
        parameters += "bool speleothemProtected(ivec3 world) { return false; } // no keep_clear\n";
    }
    const std::string header = fmt::format("voxc generated kernel \"{}\": speleothem feature '{}' ({}:{}:{}).\n",
                                           kernelName, stage.name, sourceName, stage.loc.line, stage.loc.column);
    return instantiateTemplate("speleothem_grow.glsl",
                               {{"HEADER", prefixLines(header, "// ")},
                                {"PARAMETERS", parameters},
                                {"DISPATCH_SHAPE", dispatchShapeGlsl(speleothemDispatchShape(module))}});
}

} // namespace voxc::codegen

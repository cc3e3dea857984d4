// A speleothem stage (`feature NAME = speleothems { ... }` named in the pipeline): stalactites,
// stalagmites, columns or hoodoos grown into the closed air runs of the grid earlier stages
// wrote (voxc::caves, docs/architecture.md "Speleothems"). On the GPU a prepass packs the air voxels
// into the scratch buffer, then one invocation per column writes its own column.
#include "Kinds.h"

#include "voxc/generators/caves/Speleothems.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::stages {

namespace {

constexpr std::string_view kMaskKernel = "speleothem_mask";

const SpeleothemStage& declared(const Program& program, const Stage& stage) { return program.speleothems.at(stage.index); }

std::string label(const Program& program, const Stage& stage) { return declared(program, stage).name; }

bool readsDensities(const Stage&) { return true; }

bool writesMaterials(const Program&, const Stage& stage) { return stage.material.has_value(); }

// The mask pass reads every voxel; the grow pass scans one column per column, four for hoodoos,
// and writes at most the voxels of its runs.
StageWork estimateWork(const Program& program, const Stage& stage, double voxels) {
    const SpeleothemStage& s = declared(program, stage);
    const double scans = s.params.kind == SpeleothemKind::Hoodoo ? 4.0 : 1.0;
    return {voxels * (2.0 + scans), stage.loc,
            fmt::format("speleothems '{}' ({} voxels x {} column scans)", s.name, formatWork(voxels), 1 + scans)};
}

// "<feature>_speleothems[_<material id>]": one grow kernel per feature and material.
std::string growKernelName(const Program& program, const Stage& stage) {
    std::string name = fmt::format("{}_speleothems", declared(program, stage).name);
    if (stage.material) name += fmt::format("_m{}", *stage.material);
    return name;
}

int64_t newKernels(const Program& program, const Stage& stage, std::set<std::string>& seen) {
    return int64_t(seen.insert(std::string(kMaskKernel)).second) + int64_t(seen.insert(growKernelName(program, stage)).second);
}

// A column's features grow from the closed air runs of that column (hoodoos: also of the columns
// at x - 1 and z - 1), and a run reaches as far up and down as the air does: the whole column.
StageRadius dependencyRadius(const Program& program, const Stage& stage) {
    const bool hoodoo = declared(program, stage).params.kind == SpeleothemKind::Hoodoo;
    const int32_t across = hoodoo ? 1 : 0;
    return {glm::ivec3(across, program.world.size.y - 1, across),
            hoodoo ? "the air runs of its whole column and of the columns at x - 1 and z - 1"
                   : "the air runs of its whole column"};
}

void interpret(const Program& program, const Stage& stage, DenseGrid& grid, const InterpOptions&, NonFiniteCount*) {
    const SpeleothemStage& s = declared(program, stage);
    SpeleothemParams params = s.params;
    params.material = stage.material;
    caves::ProtectedVoxel isProtected;
    if (s.clearance)
        isProtected = [set = s.clearance](glm::ivec3 world) { return pointSetClearance(*set, glm::vec3(world)); };
    caves::growSpeleothems(params, program.world.seed, program.world.origin, grid, isProtected);
}

// The index of `set` in the package's point sets, added when no field stage brought it.
uint32_t pointSetIndex(KernelPackage& package, const std::shared_ptr<const PointSet>& set) {
    auto it = std::find(package.pointSets.begin(), package.pointSets.end(), set);
    if (it != package.pointSets.end()) return uint32_t(it - package.pointSets.begin());
    package.pointSets.push_back(set);
    return uint32_t(package.pointSets.size() - 1);
}

// The mask kernel once, then a grow kernel per (feature, material) in pipeline order.
void addKernels(PlanContext& context) {
    for (const Stage& stage : context.module.pipeline) {
        if (stage.kind != Stage::Kind::Speleothems) continue;
        if (!context.kernels.contains(std::string(kMaskKernel)))
            context.kernels[std::string(kMaskKernel)] =
                context.addKernel(std::string(kMaskKernel), fmt::format("{} speleothem air mask", context.sourceName),
                                  codegen::speleothemDispatchShape(context.module),
                                  codegen::speleothemMaskKernelSource(context.module, context.sourceName));
        const std::string name = growKernelName(context.program, stage);
        if (context.kernels.contains(name)) continue;
        const SpeleothemStage& s = declared(context.program, stage);
        std::optional<uint32_t> clearanceSet;
        if (s.clearance) clearanceSet = pointSetIndex(context.package, s.clearance);
        context.kernels[name] = context.addKernel(
            name, fmt::format("{}:{}:{} speleothems {}", context.sourceName, s.loc.line, s.loc.column, s.name),
            codegen::speleothemDispatchShape(context.module),
            codegen::speleothemGrowKernelSource(context.module, s, stage.material, clearanceSet, name,
                                                context.sourceName));
    }
}

// Features only raise air to taper densities in [0.5, 1] (a union), so the bounds widen to 1.
void plan(PlanContext& context, const Stage& stage, StagePlan& plan) {
    const SpeleothemStage& s = declared(context.program, stage);
    const glm::ivec3 size = context.module.world.size;
    plan.prepassKernel = context.kernels.at(std::string(kMaskKernel));
    plan.gridKernel = context.kernels.at(growKernelName(context.program, stage));
    plan.scratchWords = uint64_t(size.x) * uint64_t(size.z) * uint64_t((size.y + 31) / 32);
    plan.attributes.emplace_back("feature", s.name);
    plan.attributes.emplace_back("speleothem_kind", std::string(caves::speleothemKindName(s.params.kind)));
    if (context.densities) context.densities->hi = std::max(context.densities->hi, 1.0f);
}

} // namespace

const StageKind kSpeleothemStage{Stage::Kind::Speleothems, "speleothems", label, readsDensities, writesMaterials,
                                 estimateWork, newKernels, dependencyRadius, interpret, addKernels, plan};

} // namespace voxc::stages

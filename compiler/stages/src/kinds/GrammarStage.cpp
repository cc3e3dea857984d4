// A grammar stage: every iteration runs the grammar's sweeps, each a kernel dispatched once per
// phase (with tile skipping, after an active-tiles kernel that lists where a rule may match).
#include "GrammarCone.h"
#include "Kinds.h"

#include <algorithm>
#include <fmt/format.h>
#include <glm/vec3.hpp>

namespace voxc::stages {

namespace {

std::string label(const Program& program, const Stage& stage) { return program.grammars.at(stage.index).name; }

bool readsDensities(const Stage&) { return true; }

bool writesMaterials(const Program& program, const Stage& stage) {
    for (const Rule& rule : program.grammars.at(stage.index).rules) {
        for (const TransformCell& cell : rule.transform)
            if (cell.material) return true;
        for (const Stamp& stamp : rule.stamps)
            if (stamp.material) return true;
    }
    return false;
}

// A rule's stamps at an anchor where its window matched: each field's nodes at every voxel of
// its grown window, times the rule's probability of firing.
double stampWork(const Program& program, const Rule& rule) {
    double work = 0.0;
    for (const Stamp& stamp : rule.stamps) {
        const glm::dvec3 grown = glm::dvec3(rule.size + 2 * stamp.reach);
        work += grown.x * grown.y * grown.z * double(program.fields.at(stamp.field).nodes.size());
    }
    return work * double(rule.probability);
}

// One iteration: every sweep tests each rule's cells at each anchor, and stamps as if every
// window matched the rule with the costliest stamps.
double iterationWork(const Program& program, const Grammar& grammar) {
    double work = 0.0;
    for (const Sweep& sweep : orderSweeps(grammar)) {
        const double anchors = double(sweep.anchorCount.x) * sweep.anchorCount.y * sweep.anchorCount.z;
        const double cells = double(sweep.window.x) * sweep.window.y * sweep.window.z;
        double stamps = 0.0;
        for (uint32_t r : sweep.rules) stamps = std::max(stamps, stampWork(program, grammar.rules[r]));
        work += anchors * (double(sweep.rules.size()) * cells + stamps);
    }
    return work;
}

StageWork estimateWork(const Program& program, const Stage& stage, double) {
    const Grammar& grammar = program.grammars[stage.index];
    const double perIteration = iterationWork(program, grammar);
    return {perIteration * grammar.iterations, stage.loc.line ? stage.loc : grammar.loc,
            fmt::format("grammar '{}' ({} iterations x {} window cells tested per iteration: anchors x rules x "
                        "cells over its sweeps)",
                        grammar.name, grammar.iterations, formatWork(perIteration))};
}

// One kernel per window size (sweep) of a grammar not run before.
int64_t newKernels(const Program& program, const Stage& stage, std::set<std::string>& seen) {
    if (!seen.insert(fmt::format("grammar {}", stage.index)).second) return 0;
    // A sweep kernel per window size, and a stamp pass per sweep with stamps.
    const Grammar& grammar = program.grammars[stage.index];
    int64_t kernels = 0;
    for (const Sweep& sweep : orderSweeps(grammar)) {
        const bool stamps = std::any_of(sweep.rules.begin(), sweep.rules.end(),
                                        [&](uint32_t r) { return !grammar.rules[r].stamps.empty(); });
        kernels += stamps ? 2 : 1;
    }
    return kernels;
}

StageRadius dependencyRadius(const Program& program, const Stage& stage) {
    const Grammar& grammar = program.grammars.at(stage.index);
    const glm::ivec3 radius = grammarConeRadius(grammar, program.world.size - 1);
    return {radius, fmt::format("{} iteration{} of {}, each phase moving a voxel's reach to the ends of the "
                                "windows holding it",
                                grammar.iterations, grammar.iterations == 1 ? "" : "s", describeSweeps(grammar))};
}

void interpret(const Program& program, const Stage& stage, DenseGrid& grid, const InterpOptions& options,
               NonFiniteCount* nonFinite) {
    runGrammar(program, stage.index, grid, options, nonFinite);
}

std::string sweepKey(const ir::IrGrammar& grammar, const ir::IrSweep& sweep) {
    return fmt::format("{}_sweep{}", grammar.name, sweep.index);
}

// Kernels of every grammar are built once, even if the pipeline runs it more than once; the
// stamp passes follow the sweep kernels, then the tile-skipping kernels (a sweep without live
// rules needs none).
void addKernels(PlanContext& context) {
    const std::optional<codegen::OccupancyLevel> level = codegen::occupancyLevel(context.module);
    for (const ir::IrGrammar& grammar : context.module.grammars)
        for (const ir::IrSweep& sweep : grammar.sweeps) {
            const std::string name = sweepKey(grammar, sweep);
            const std::string origin =
                fmt::format("{}:{}:{} grammar {}, window [{},{},{}]", context.sourceName, grammar.loc.line,
                            grammar.loc.column, grammar.name, sweep.window.x, sweep.window.y, sweep.window.z);
            context.kernels[name] =
                context.addKernel(name, origin, codegen::sweepDispatchShape(sweep),
                                  codegen::sweepKernelSource(grammar, sweep, name, context.sourceName, level));
        }
    for (const ir::IrGrammar& grammar : context.module.grammars)
        for (const ir::IrSweep& sweep : grammar.sweeps) {
            if (!codegen::sweepHasStamps(sweep)) continue;
            const std::string name = sweepKey(grammar, sweep) + "_stamps";
            const std::string origin = context.package.kernels[context.kernels.at(sweepKey(grammar, sweep))].origin;
            context.kernels[name] = context.addKernel(
                name, origin, codegen::stampDispatchShape(),
                codegen::stampKernelSource(context.module, grammar, sweep, name, context.sourceName));
        }
    // A sweep with stamps runs over every anchor (its stamp pass reads each anchor's choice).
    for (const ir::IrGrammar& grammar : context.module.grammars)
        for (const ir::IrSweep& sweep : grammar.sweeps) {
            if (sweep.rules.empty() || codegen::sweepHasStamps(sweep)) continue;
            const std::string name = sweepKey(grammar, sweep) + "_active_tiles";
            const std::string origin = context.package.kernels[context.kernels.at(sweepKey(grammar, sweep))].origin;
            context.kernels[name] =
                context.addKernel(name, origin, codegen::activeTilesDispatchShape(),
                                  codegen::activeTilesKernelSource(grammar, sweep, name, context.sourceName, level));
        }
    if (!context.module.grammars.empty())
        context.package.tileRangesKernel = context.addKernel("tile_ranges", "voxc runtime: tile density ranges",
                                                             codegen::tileRangesDispatchShape(),
                                                             codegen::tileRangesKernelSource(level));
}

// After a grammar the density bounds are not tracked.
void plan(PlanContext& context, const Stage& stage, StagePlan& plan) {
    const ir::IrGrammar& grammar = context.module.grammars.at(stage.index);
    const Grammar& checked = context.program.grammars.at(grammar.programIndex);
    GrammarPlan sweeps;
    sweeps.name = grammar.name;
    sweeps.iterations = uint32_t(grammar.iterations);
    for (const ir::IrSweep& irSweep : grammar.sweeps) {
        Sweep sweep;
        sweep.window = irSweep.window;
        sweep.anchorCount = irSweep.anchorCount;
        sweep.phaseCount = irSweep.phaseCount;
        SweepPlan sweepPlan;
        sweepPlan.kernel = context.kernels.at(sweepKey(grammar, irSweep));
        const auto activeTiles = context.kernels.find(sweepKey(grammar, irSweep) + "_active_tiles");
        if (activeTiles != context.kernels.end()) sweepPlan.activeTilesKernel = activeTiles->second;
        const auto stamps = context.kernels.find(sweepKey(grammar, irSweep) + "_stamps");
        if (stamps != context.kernels.end()) {
            sweepPlan.stampKernel = stamps->second;
            sweepPlan.stampReach = codegen::sweepStampReach(irSweep);
            plan.scratchWords = std::max(plan.scratchWords, codegen::sweepFiredWords(irSweep));
        }
        sweepPlan.window = irSweep.window;
        sweepPlan.phaseCount = irSweep.phaseCount;
        fillPhaseAnchors(sweepPlan, checked, sweep);
        sweeps.sweeps.push_back(std::move(sweepPlan));
    }
    plan.attributes.emplace_back("grammar", grammar.name);
    plan.grammar = std::move(sweeps);
    context.densities.reset();
}

} // namespace

const StageKind kGrammarStage{Stage::Kind::Grammar, "grammar", label,     readsDensities, writesMaterials, estimateWork,
                              newKernels,           dependencyRadius, interpret, addKernels, plan};

} // namespace voxc::stages

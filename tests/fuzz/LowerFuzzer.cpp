// libFuzzer target: every input that checks cleanly is lowered to the IR (all passes, the IR
// printed after each) and every kernel's GLSL is generated, with each field stage's chunk boxes.
// glslang and SPIR-V validation cost far more than the rest, so only a sample of the inputs
// (chosen by a hash of the bytes, so a reproducer replays the same way) goes through the whole
// compileProgram. A Program the checker accepted must lower and compile: any exception
// is a finding.
#include "FuzzInput.h"
#include "FuzzLimits.h"
#include "voxc/codegen/KernelSources.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/ir/Lower.h"
#include "voxc/ir/Ir.h"

#include <algorithm>
#include <string_view>

namespace {

constexpr uint32_t kCompileOneIn = 16;

uint32_t hashBytes(const uint8_t* data, size_t size) {
    uint32_t hash = 2166136261u; // FNV-1a
    for (size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 16777619u;
    return hash;
}

void generateGlsl(const voxc::ir::IrModule& module) {
    using namespace voxc::codegen;
    const std::string_view sourceName = "fuzz.vox";
    if (std::any_of(module.pipeline.begin(), module.pipeline.end(),
                    [](const voxc::Stage& stage) { return stage.kind == voxc::Stage::Kind::Start; }))
        (void)startKernelSource(module, sourceName);
    for (const voxc::Stage& stage : module.pipeline) {
        if (stage.kind != voxc::Stage::Kind::Field) continue;
        const voxc::ir::IrField& field = module.fields.at(stage.index);
        (void)fieldBoxes(module, field, stage.mode, stage.material, std::nullopt);
        (void)fieldKernelSource(module, field, stage.mode, stage.material, {stage}, field.name, sourceName);
    }
    const std::optional<OccupancyLevel> level = occupancyLevel(module);
    (void)tileRangesKernelSource(level);
    for (const voxc::ir::IrGrammar& grammar : module.grammars)
        for (const voxc::ir::IrSweep& sweep : grammar.sweeps) {
            (void)sweepKernelSource(grammar, sweep, grammar.name, sourceName, level);
            if (!sweep.rules.empty()) (void)activeTilesKernelSource(grammar, sweep, grammar.name, sourceName, level);
        }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const voxc::CheckResult result = voxc::checkSource(voxc::fuzz::sourceFromBytes(data, size), voxc::fuzz::fuzzLimits());
    if (!result.program) return 0;
    if (hashBytes(data, size) % kCompileOneIn == 0) {
        (void)voxc::compileProgram(*result.program);
        return 0;
    }
    const voxc::ir::IrModule module = voxc::ir::lowerProgram(
        *result.program, {[](std::string_view, const voxc::ir::IrModule& after) { (void)voxc::ir::printIr(after); }});
    generateGlsl(module);
    return 0;
}

#include "voxc/ir/passes/RemoveDeadStages.h"

#include <algorithm>

namespace voxc::ir {

namespace {

bool writesMaterials(const IrModule& module, const Stage& stage) {
    switch (stage.kind) {
    case Stage::Kind::Start:
        return std::any_of(module.start.begin(), module.start.end(),
                           [](const StartShape& shape) { return shape.material.has_value(); });
    case Stage::Kind::Grammar:
        for (const IrSweep& sweep : module.grammars.at(stage.index).sweeps)
            for (const IrRule& rule : sweep.rules)
                for (const TransformCell& cell : rule.transform)
                    if (cell.material) return true;
        return false;
    case Stage::Kind::Field: return stage.material.has_value();
    }
    return true;
}

// Whether the stage's result depends on the densities before it: only a set's does not
// (combineField's set writes f, and its material test looks at f alone).
bool readsDensities(const Stage& stage) { return !(stage.kind == Stage::Kind::Field && stage.mode == FieldMode::Set); }

} // namespace

IrModule removeDeadStages(IrModule module) {
    // Backwards from the result: a stage is live when the densities after it are still needed
    // or it writes materials (the material channel always reaches the result).
    std::vector<bool> live(module.pipeline.size(), false);
    bool densitiesNeeded = true;
    for (size_t i = module.pipeline.size(); i-- > 0;) {
        const Stage& stage = module.pipeline[i];
        live[i] = densitiesNeeded || writesMaterials(module, stage);
        if (live[i]) densitiesNeeded = readsDensities(stage);
    }
    std::vector<Stage> kept;
    for (size_t i = 0; i < module.pipeline.size(); ++i)
        (live[i] ? kept : module.deadStages).push_back(module.pipeline[i]);
    module.pipeline = std::move(kept);
    return module;
}

} // namespace voxc::ir

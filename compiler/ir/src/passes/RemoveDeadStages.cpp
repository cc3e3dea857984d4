#include "voxc/ir/passes/RemoveDeadStages.h"

namespace voxc::ir {

IrModule removeDeadStages(IrModule module) {
    // Backwards from the result: a stage is live when the densities after it are still needed
    // or it writes materials (the material channel always reaches the result).
    std::vector<bool> live(module.pipeline.size(), false);
    bool densitiesNeeded = true;
    for (size_t i = module.pipeline.size(); i-- > 0;) {
        const Stage& stage = module.pipeline[i];
        live[i] = densitiesNeeded || stage.writesMaterials;
        if (live[i]) densitiesNeeded = stage.readsDensities;
    }
    std::vector<Stage> kept;
    for (size_t i = 0; i < module.pipeline.size(); ++i)
        (live[i] ? kept : module.deadStages).push_back(module.pipeline[i]);
    module.pipeline = std::move(kept);
    return module;
}

} // namespace voxc::ir

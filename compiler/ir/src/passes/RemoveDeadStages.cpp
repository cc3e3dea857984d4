#include "voxc/ir/passes/RemoveDeadStages.h"

namespace voxc::ir {

IrModule removeDeadStages(IrModule module) {
    size_t firstLive = 0;
    for (size_t i = 0; i < module.pipeline.size(); ++i) {
        const Stage& stage = module.pipeline[i];
        if (stage.kind == Stage::Kind::Field && stage.mode == FieldMode::Set) firstLive = i;
    }
    const auto live = module.pipeline.begin() + std::ptrdiff_t(firstLive);
    module.deadStages.insert(module.deadStages.end(), module.pipeline.begin(), live);
    module.pipeline.erase(module.pipeline.begin(), live);
    return module;
}

} // namespace voxc::ir

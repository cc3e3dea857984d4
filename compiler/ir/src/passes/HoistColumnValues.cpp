#include "voxc/ir/passes/HoistColumnValues.h"

namespace voxc::ir {

IrModule hoistColumnValues(IrModule module) {
    for (IrField& field : module.fields) {
        field.perColumn.assign(field.nodes.size(), true);
        for (size_t i = 0; i < field.nodes.size(); ++i) {
            const FieldNode& node = field.nodes[i];
            if (node.kind == FieldNode::Kind::Input)
                field.perColumn[i] = node.input != FieldInput::LocalY && node.input != FieldInput::WorldY;
            for (uint32_t operand : node.operands)
                if (!field.perColumn[operand]) field.perColumn[i] = false;
        }
    }
    return module;
}

} // namespace voxc::ir

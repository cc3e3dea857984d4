#include "voxc/ir/passes/EliminateCommonSubexpressions.h"

#include <cstring>
#include <map>
#include <tuple>
#include <vector>

namespace voxc::ir {

namespace {

// What makes two nodes equal; floats compare by bit pattern so 0 and -0 stay apart.
using NodeKey = std::tuple<FieldNode::Kind, Type, uint32_t, uint32_t, uint32_t, int32_t, bool, FieldInput, uint32_t,
                           uint32_t, std::vector<uint32_t>, const PointSet*, const SampledMap*>;

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

NodeKey keyOf(const FieldNode& n) {
    const bool constant = n.kind == FieldNode::Kind::Constant;
    return {n.kind,
            n.type,
            constant ? bits(n.constant.x) : 0u,
            constant ? bits(n.constant.y) : 0u,
            constant ? bits(n.constant.z) : 0u,
            constant ? n.constantInt : 0,
            constant && n.constantBool,
            n.kind == FieldNode::Kind::Input ? n.input : FieldInput::LocalX,
            n.kind == FieldNode::Kind::Call ? n.function : 0u,
            n.kind == FieldNode::Kind::Component ? n.component : 0u,
            n.operands,
            n.pointSet.get(),
            n.map.get()};
}

void eliminate(IrField& field) {
    // Merge: each node maps to the first earlier node with the same key.
    std::vector<uint32_t> canonical(field.nodes.size());
    std::map<NodeKey, uint32_t> seen;
    for (uint32_t i = 0; i < field.nodes.size(); ++i) {
        FieldNode& node = field.nodes[i];
        for (uint32_t& operand : node.operands) operand = canonical[operand];
        canonical[i] = seen.try_emplace(keyOf(node), i).first->second;
    }
    const uint32_t root = canonical[field.root];
    // Keep what the root uses, walking users before operands.
    std::vector<bool> used(field.nodes.size(), false);
    used[root] = true;
    for (uint32_t i = root + 1; i-- > 0;)
        if (used[i])
            for (uint32_t operand : field.nodes[i].operands) used[operand] = true;
    std::vector<uint32_t> renumber(field.nodes.size(), 0);
    std::vector<FieldNode> kept;
    for (uint32_t i = 0; i < field.nodes.size(); ++i) {
        if (!used[i]) continue;
        FieldNode node = std::move(field.nodes[i]);
        for (uint32_t& operand : node.operands) operand = renumber[operand];
        renumber[i] = uint32_t(kept.size());
        kept.push_back(std::move(node));
    }
    field.nodes = std::move(kept);
    field.root = renumber[root];
    field.perColumn.clear(); // node numbers changed; hoisting runs after this pass
}

} // namespace

IrModule eliminateCommonSubexpressions(IrModule module) {
    for (IrField& field : module.fields) eliminate(field);
    return module;
}

} // namespace voxc::ir

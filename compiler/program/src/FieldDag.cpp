#include "voxc/program/FieldDag.h"

#include <bit>

namespace voxc {

uint32_t FieldDag::add(FieldNode node) {
    // Float constants compare by bit pattern, so 0 and -0 stay distinct.
    Key key{uint8_t(node.kind),
            uint8_t(node.type),
            std::bit_cast<uint32_t>(node.constant.x),
            std::bit_cast<uint32_t>(node.constant.y),
            std::bit_cast<uint32_t>(node.constant.z),
            node.constantInt,
            node.constantBool,
            uint8_t(node.input),
            node.function,
            node.component,
            node.operands,
            node.pointSet.get(),
            node.map.get()};
    auto [it, inserted] = index_.emplace(std::move(key), uint32_t(nodes_.size()));
    if (inserted) nodes_.push_back(std::move(node));
    return it->second;
}

std::vector<FieldNode> FieldDag::reachableFrom(uint32_t root, uint32_t& newRoot) const {
    std::vector<bool> used(nodes_.size(), false);
    used[root] = true;
    // Operands precede their users, so one backward pass marks everything reachable.
    for (uint32_t i = root + 1; i-- > 0;)
        if (used[i])
            for (uint32_t operand : nodes_[i].operands) used[operand] = true;
    std::vector<uint32_t> renumbered(nodes_.size(), 0);
    std::vector<FieldNode> out;
    for (uint32_t i = 0; i <= root; ++i) {
        if (!used[i]) continue;
        renumbered[i] = uint32_t(out.size());
        FieldNode node = nodes_[i];
        for (uint32_t& operand : node.operands) operand = renumbered[operand];
        out.push_back(std::move(node));
    }
    newRoot = renumbered[root];
    return out;
}

} // namespace voxc

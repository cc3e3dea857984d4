#pragma once
// Builds a Field's node list with hash-consing: adding a node equal to one already present
// (same kind, type, payload and operands) returns the existing index, so repeated
// subexpressions, let bindings and materialised literals share one node. The checker lowers
// field expressions with it and the feature generators (voxc_generators) build their fields.
#include "voxc/program/Field.h"

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace voxc {

class FieldDag {
public:
    uint32_t add(FieldNode node);
    const FieldNode& operator[](uint32_t index) const { return nodes_[index]; }

    // The nodes `root` depends on, in order, renumbered; `root` becomes the last node.
    std::vector<FieldNode> reachableFrom(uint32_t root, uint32_t& newRoot) const;

private:
    using Key = std::tuple<uint8_t, uint8_t, uint32_t, uint32_t, uint32_t, int32_t, bool, uint8_t, uint32_t, uint32_t,
                           std::vector<uint32_t>, const PointSet*, const SampledMap*>;
    std::vector<FieldNode> nodes_;
    std::map<Key, uint32_t> index_;
};

} // namespace voxc

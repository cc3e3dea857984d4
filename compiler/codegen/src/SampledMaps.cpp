#include "voxc/codegen/SampledMaps.h"

#include "voxc/core/Errors.h"

#include <algorithm>

namespace voxc::codegen {

std::vector<std::shared_ptr<const SampledMap>> mapsOf(const ir::IrModule& module) {
    std::vector<std::shared_ptr<const SampledMap>> maps;
    for (const ir::IrField& field : module.fields)
        for (const FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::Map && std::find(maps.begin(), maps.end(), node.map) == maps.end())
                maps.push_back(node.map);
    return maps;
}

std::shared_ptr<const SolveTable> mapTable(const SampledMap& map) {
    if (map.values.empty())
        throw InternalError("the terrain '" + map.name + "' was not solved before its map was uploaded");
    auto table = std::make_shared<SolveTable>();
    table->size = map.size;
    table->density = map.values;
    table->source = "map";
    return table;
}

} // namespace voxc::codegen

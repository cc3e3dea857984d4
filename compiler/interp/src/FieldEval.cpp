#include "voxc/interp/FieldEval.h"

#include "voxc/program/Semantics.h"

#include "voxc/core/Errors.h"

#include <algorithm>

namespace voxc {

FieldEvaluator::FieldEvaluator(const Field& field, glm::ivec3 origin, glm::ivec3 localBase)
    : field_(field), origin_(origin), localBase_(localBase), functions_(field.nodes.size(), nullptr), values_(field.nodes.size()) {
    VOXC_ASSERT(field.root < field.nodes.size());
    size_t maxOperands = 0;
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        for (uint32_t operand : node.operands) VOXC_ASSERT(operand < i); // topological order
        maxOperands = std::max(maxOperands, node.operands.size());
        if (node.kind == FieldNode::Kind::Call) {
            VOXC_ASSERT(node.function < functions().size());
            functions_[i] = &functions()[node.function];
        }
        // A map's heights come with the run's solve (stages::solveBlocks), never with the check.
        if (node.kind == FieldNode::Kind::Map && node.map->values.empty())
            throw InternalError("the terrain '" + node.map->name + "' was not solved before a field sampled it");
    }
    arguments_.reserve(maxOperands);
}

const std::vector<Value>& FieldEvaluator::evaluate(glm::ivec3 local) {
    return evaluateAt(glm::vec3(localBase_ + local), origin_ + local);
}

const std::vector<Value>& FieldEvaluator::evaluateAt(glm::vec3 position, glm::ivec3 world) {
    for (size_t i = 0; i < field_.nodes.size(); ++i) {
        const FieldNode& node = field_.nodes[i];
        Value& out = values_[i];
        switch (node.kind) {
        case FieldNode::Kind::Constant:
            out.type = node.type;
            out.v = node.constant;
            out.i = node.constantInt;
            out.b = node.constantBool;
            break;
        case FieldNode::Kind::Input: {
            const int axis = int(node.input) % 3;
            const bool isWorld = node.input >= FieldInput::WorldX;
            out = Value::makeFloat(isWorld ? float(world[axis]) : position[axis]);
            break;
        }
        case FieldNode::Kind::Component:
            out = Value::makeFloat(values_[node.operands[0]].v[int(node.component)]);
            break;
        case FieldNode::Kind::PointSet: // the lists binned at check time; any lists give the same floats
            out = Value::makeVec2(pointSetDistances(*node.pointSet, node.pointSet->bins, values_[node.operands[0]].v));
            break;
        case FieldNode::Kind::Map:
            out = Value::makeFloat(node.map->dimensions == 2
                                       ? sampleMap(*node.map, values_[node.operands[0]].v.x, values_[node.operands[1]].v.x)
                                       : sampleVolume(*node.map, values_[node.operands[0]].v.x,
                                                      values_[node.operands[1]].v.x, values_[node.operands[2]].v.x));
            break;
        case FieldNode::Kind::Call:
            arguments_.clear();
            for (uint32_t operand : node.operands) arguments_.push_back(values_[operand]);
            out = functions_[i]->eval(arguments_);
            break;
        }
    }
    return values_;
}

void runField(const Program& program, const Stage& stage, DenseGrid& grid, NonFiniteCount* nonFinite,
              const std::function<void(double)>& progress) {
    VOXC_ASSERT(stage.kind == Stage::Kind::Field && stage.index < program.fields.size());
    VOXC_ASSERT(grid.size() == program.world.size);
    FieldEvaluator evaluator(program.fields[stage.index], program.world.origin, program.world.localBase);
    NonFiniteCount uncounted;
    NonFiniteCount& replaced = nonFinite ? *nonFinite : uncounted;
    const glm::ivec3 size = grid.size();
    for (int z = 0; z < size.z; ++z) {
        if (progress) progress(double(z) / double(size.z));
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                float& d = grid.at({x, y, z});
                uint8_t& m = grid.materialAt({x, y, z});
                const float f = replaced.replace(evaluator.density({x, y, z}), grid.index({x, y, z}));
                const VoxelState voxel = combineField(stage.mode, stage.material, f, {d, m});
                d = voxel.density;
                m = voxel.material;
            }
    }
}

} // namespace voxc

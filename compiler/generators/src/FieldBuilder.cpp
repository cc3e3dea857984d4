#include "FieldBuilder.h"

#include "voxc/builtins/Functions.h"
#include "voxc/core/Errors.h"

namespace voxc::generators {

uint32_t FieldBuilder::number(double value) {
    FieldNode node;
    node.kind = FieldNode::Kind::Constant;
    node.type = Type::Float;
    node.constant = glm::vec3(float(value), 0.0f, 0.0f);
    return dag_.add(node);
}

uint32_t FieldBuilder::vec3(glm::dvec3 value) {
    FieldNode node;
    node.kind = FieldNode::Kind::Constant;
    node.type = Type::Vec3;
    node.constant = glm::vec3(value);
    return dag_.add(node);
}

uint32_t FieldBuilder::seed(uint32_t value) {
    FieldNode node;
    node.kind = FieldNode::Kind::Constant;
    node.type = Type::Int;
    node.constantInt = int32_t(value);
    return dag_.add(node);
}

uint32_t FieldBuilder::inputs(FieldInput x) {
    uint32_t axes[3];
    for (int i = 0; i < 3; ++i) {
        FieldNode node;
        node.kind = FieldNode::Kind::Input;
        node.input = FieldInput(uint8_t(x) + i);
        axes[i] = dag_.add(node);
    }
    return call("vec3", {axes[0], axes[1], axes[2]});
}

uint32_t FieldBuilder::position() { return inputs(FieldInput::LocalX); }

uint32_t FieldBuilder::worldPosition() { return inputs(FieldInput::WorldX); }

uint32_t FieldBuilder::component(uint32_t vector, uint32_t index) {
    FieldNode node;
    node.kind = FieldNode::Kind::Component;
    node.type = Type::Float;
    node.component = index;
    node.operands = {vector};
    return dag_.add(node);
}

uint32_t FieldBuilder::call(std::string_view name, std::initializer_list<uint32_t> operands) {
    const FunctionInfo* info = findFunction(name);
    VOXC_ASSERT(info != nullptr);
    std::vector<Type> types;
    for (uint32_t operand : operands) types.push_back(dag_[operand].type);
    const std::optional<Type> result = info->typeRule(types);
    VOXC_ASSERT(result.has_value());
    FieldNode node;
    node.kind = FieldNode::Kind::Call;
    node.type = *result;
    node.function = uint32_t(info - functions().data());
    node.operands = operands;
    return dag_.add(node);
}

uint32_t FieldBuilder::add(const FieldNode& node) { return dag_.add(node); }

Field FieldBuilder::field(uint32_t root) const {
    Field out;
    out.nodes = dag_.reachableFrom(root, out.root);
    return out;
}

} // namespace voxc::generators

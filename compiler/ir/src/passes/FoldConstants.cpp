#include "voxc/ir/passes/FoldConstants.h"

#include "voxc/builtins/Functions.h"

#include <cmath>
#include <vector>

namespace voxc::ir {

namespace {

int floatComponents(Type type) { return type == Type::Vec3 ? 3 : type == Type::Vec2 ? 2 : type == Type::Float; }

// Finite and normal (or zero) in every component: a value both sides represent identically.
bool foldable(const Value& value) {
    for (int c = 0; c < floatComponents(value.type); ++c) {
        const int kind = std::fpclassify(value.v[c]);
        if (kind != FP_NORMAL && kind != FP_ZERO) return false;
    }
    return true;
}

void makeConstant(FieldNode& node, const Value& value) {
    node.kind = FieldNode::Kind::Constant;
    node.type = value.type;
    node.constant = glm::vec3(0.0f);
    for (int c = 0; c < floatComponents(value.type); ++c) node.constant[c] = value.v[c];
    node.constantInt = value.type == Type::Int ? value.i : 0;
    node.constantBool = value.type == Type::Bool && value.b;
    node.operands.clear();
}

void foldField(IrField& field) {
    std::vector<Value> arguments;
    for (FieldNode& node : field.nodes) {
        if (node.kind != FieldNode::Kind::Call && node.kind != FieldNode::Kind::Component) continue;
        arguments.clear();
        bool allConstant = true;
        for (uint32_t operand : node.operands) {
            const FieldNode& source = field.nodes[operand];
            allConstant = allConstant && source.kind == FieldNode::Kind::Constant && foldable(constantValue(source));
            arguments.push_back(constantValue(source));
        }
        if (!allConstant) continue;
        Value result;
        if (node.kind == FieldNode::Kind::Component) {
            result = Value::makeFloat(arguments[0].v[int(node.component)]);
        } else {
            const FunctionInfo& info = functions()[node.function];
            if (info.tolerance != 0.0f) continue;
            result = info.eval(arguments);
        }
        if (result.type != node.type || !foldable(result)) continue;
        makeConstant(node, result);
    }
}

} // namespace

IrModule foldConstants(IrModule module) {
    for (IrField& field : module.fields) foldField(field);
    return module;
}

} // namespace voxc::ir

#include "voxc/interp/FieldRows.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <string_view>

namespace voxc {

namespace {

int components(Type type) { return type == Type::Vec3 ? 3 : type == Type::Vec2 ? 2 : 1; }
bool isFloatLike(Type type) { return type == Type::Float || type == Type::Vec2 || type == Type::Vec3; }

// The row loops, compiled for the host's widest SIMD (the same IEEE operation per lane). An
// operand the same along the row is its lane 0 (`Uniform`), read as a scalar.
struct Add {
    static float apply(float a, float b) { return a + b; }
};
struct Subtract {
    static float apply(float a, float b) { return a - b; }
};
struct Multiply {
    static float apply(float a, float b) { return a * b; }
};
struct Divide {
    static float apply(float a, float b) { return a / b; }
};

template <typename Op, bool AUniform, bool BUniform>
VOXC_SIMD_KERNEL void binaryRow(const float* a, const float* b, float* out, int n) {
    const float a0 = a[0], b0 = b[0];
    for (int i = 0; i < n; ++i) out[i] = Op::apply(AUniform ? a0 : a[i], BUniform ? b0 : b[i]);
}

// out = a op b over the row, or its lane 0 alone where both are uniform (then so is the result).
template <typename Op>
void binary(const float* a, bool aUniform, const float* b, bool bUniform, float* out, int n) {
    if (aUniform && bUniform) out[0] = Op::apply(a[0], b[0]);
    else if (aUniform) atHostSimd<binaryRow<Op, true, false>>(a, b, out, n);
    else if (bUniform) atHostSimd<binaryRow<Op, false, true>>(a, b, out, n);
    else atHostSimd<binaryRow<Op, false, false>>(a, b, out, n);
}

VOXC_SIMD_KERNEL void negateRow(const float* a, float* out, int n) {
    for (int i = 0; i < n; ++i) out[i] = -a[i];
}
VOXC_SIMD_KERNEL void countRow(float* out, int first, int n) {
    for (int i = 0; i < n; ++i) out[i] = float(first + i);
}

} // namespace

FieldRowEvaluator::FieldRowEvaluator(const Field& field, glm::ivec3 origin, glm::ivec3 localBase)
    : field_(field), origin_(origin), localBase_(localBase), scalar_(field, origin, localBase), plans_(field.nodes.size()),
      floats_(field.nodes.size() * 3 * kRowVoxels), ints_(field.nodes.size() * kRowVoxels),
      bools_(field.nodes.size() * kRowVoxels) {
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        NodePlan& plan = plans_[i];
        const auto anyOperandVaries = [&] {
            return std::any_of(node.operands.begin(), node.operands.end(), [&](uint32_t o) { return !plans_[o].uniform; });
        };
        std::string_view name;
        if (node.kind == FieldNode::Kind::Call) name = functions()[node.function].name;
        const bool arithmetic = isFloatLike(node.type) && (name == "add" || name == "sub" || name == "mul" ||
                                                           name == "div" || name == "neg");
        switch (node.kind) {
        case FieldNode::Kind::Constant: break;
        case FieldNode::Kind::Input:
            plan.varies[0] = node.input == FieldInput::LocalX || node.input == FieldInput::WorldX;
            plan.op = RowOp::InputX;
            break;
        case FieldNode::Kind::Component:
            plan.varies[0] = plans_[node.operands[0]].varies[node.component];
            plan.op = RowOp::Component;
            break;
        case FieldNode::Kind::Call:
            if (arithmetic) {
                for (int c = 0; c < components(node.type); ++c)
                    plan.varies[c] = std::any_of(node.operands.begin(), node.operands.end(),
                                                 [&](uint32_t o) { return !uniformLanes(o, c); });
                plan.op = name == "add" ? RowOp::Add : name == "sub" ? RowOp::Subtract : name == "mul" ? RowOp::Multiply
                          : name == "div" ? RowOp::Divide : RowOp::Negate;
                break;
            }
            if (name == "vec2" || name == "vec3") {
                for (size_t c = 0; c < node.operands.size(); ++c) plan.varies[c] = plans_[node.operands[c]].varies[0];
                plan.op = RowOp::Construct;
                break;
            }
            std::fill(plan.varies, plan.varies + 3, anyOperandVaries());
            if (name == "fbm" || name == "turbulence" || name == "ridged" || name == "perlin3") {
                const NodePlan& position = plans_[node.operands[0]];
                const bool restUniform = std::all_of(node.operands.begin() + 1, node.operands.end(),
                                                     [&](uint32_t o) { return plans_[o].uniform; });
                if (!position.varies[1] && !position.varies[2] && restUniform) {
                    plan.op = RowOp::Fractal;
                    plan.fold = name == "turbulence" ? FractalFold::Absolute
                                : name == "ridged"   ? FractalFold::Ridged
                                                     : FractalFold::Sum;
                }
            }
            break;
        case FieldNode::Kind::PointSet:
        case FieldNode::Kind::Map: std::fill(plan.varies, plan.varies + 3, anyOperandVaries()); break;
        }
        plan.uniform = !std::any_of(plan.varies, plan.varies + components(node.type), [](bool v) { return v; });
        plan.constant = node.kind == FieldNode::Kind::Constant;
        if (plan.uniform) plan.scalar = true;
        else if (plan.op != RowOp::Fractal) // (a fractal reads its uniform arguments' scalars)
            for (uint32_t o : node.operands)
                if (plans_[o].uniform) plans_[o].readAsLanes = true;
    }
    lanes_.resize(field.nodes.size() * 3);
    for (size_t i = 0; i < lanes_.size(); ++i) lanes_[i] = floats_.data() + i * kRowVoxels;
    for (uint32_t i = 0; i < plans_.size(); ++i) {
        // A vector's components and a component of one share their operands' lanes.
        const FieldNode& node = field.nodes[i];
        if (plans_[i].uniform) continue;
        if (plans_[i].op == RowOp::Construct)
            for (size_t c = 0; c < node.operands.size(); ++c) lanes_[i * 3 + c] = lanes_[size_t(node.operands[c]) * 3];
        if (plans_[i].op == RowOp::Component) lanes_[i * 3] = lanes_[size_t(node.operands[0]) * 3 + node.component];
    }
    // The root's own lanes are the caller's row, unless they are another node's.
    writesRoot_ = !plans_[field.root].uniform && plans_[field.root].op != RowOp::Component;
    for (const FieldNode& node : field.nodes)
        for (uint32_t o : node.operands) writesRoot_ = writesRoot_ && o != field.root;
    // A uniform node may read a varying one (the y of a position that varies in x): it is
    // evaluated at the row's first voxel too, for its uniform components.
    for (size_t i = field.nodes.size(); i-- > 0;)
        if (plans_[i].scalar)
            for (uint32_t o : field.nodes[i].operands) plans_[o].scalar = true;
    // Constants once for every row.
    for (uint32_t i = 0; i < plans_.size(); ++i)
        if (plans_[i].constant) {
            scalar_.evaluateNode(i, glm::vec3(0.0f), glm::ivec3(0));
            if (plans_[i].readAsLanes) storeUniform(i);
        }
}

bool FieldRowEvaluator::uniformLanes(uint32_t node, int component) const {
    const NodePlan& plan = plans_[node];
    return plan.uniform || !plan.varies[field_.nodes[node].type == Type::Float ? 0 : component];
}

Value FieldRowEvaluator::laneValue(uint32_t node, int lane) {
    const NodePlan& plan = plans_[node];
    if (plan.uniform) return scalar_.values()[node];
    const size_t at = size_t(node) * kRowVoxels + size_t(lane);
    const auto component = [&](int c) { return floats(node, c)[plan.varies[c] ? lane : 0]; };
    switch (field_.nodes[node].type) {
    case Type::Int: return Value::makeInt(ints_[at]);
    case Type::Bool: return Value::makeBool(bools_[at] != 0);
    case Type::Float: return Value::makeFloat(component(0));
    case Type::Vec2: return Value::makeVec2({component(0), component(1)});
    case Type::Vec3: return Value::makeVec3({component(0), component(1), component(2)});
    }
    throw InternalError("a field node of unknown type");
}

void FieldRowEvaluator::storeLane(uint32_t node, int lane, const Value& value) {
    const Type type = field_.nodes[node].type;
    const size_t at = size_t(node) * kRowVoxels + size_t(lane);
    if (type == Type::Int) ints_[at] = value.i;
    else if (type == Type::Bool) bools_[at] = value.b ? 1 : 0;
    else
        for (int c = 0; c < components(type); ++c) floats(node, c)[lane] = value.v[c];
}

void FieldRowEvaluator::storeUniform(uint32_t node) {
    const Value& value = scalar_.values()[node];
    if (field_.nodes[node].type == Type::Int || field_.nodes[node].type == Type::Bool) return; // (read as scalars)
    for (int c = 0; c < components(field_.nodes[node].type); ++c) floats(node, c)[0] = value.v[c];
}

void FieldRowEvaluator::evaluateVarying(uint32_t index, glm::ivec3 first, int count) {
    const FieldNode& node = field_.nodes[index];
    const NodePlan& plan = plans_[index];
    // Operand k's lanes of component c (a float operand's only component for any c).
    const auto in = [&](size_t k, int c) {
        const uint32_t operand = node.operands[k];
        return floats(operand, field_.nodes[operand].type == Type::Float ? 0 : c);
    };
    switch (plan.op) {
    case RowOp::InputX: {
        const int base = (node.input == FieldInput::WorldX ? origin_.x : localBase_.x) + first.x;
        atHostSimd<countRow>(floats(index, 0), base, count);
        return;
    }
    case RowOp::Component:
    case RowOp::Construct: return; // their lanes are their operands'
    case RowOp::Negate:
        for (int c = 0; c < components(node.type); ++c) {
            if (plan.varies[c]) atHostSimd<negateRow>(in(0, c), floats(index, c), count);
            else floats(index, c)[0] = -in(0, c)[0];
        }
        return;
    case RowOp::Add:
    case RowOp::Subtract:
    case RowOp::Multiply:
    case RowOp::Divide:
        for (int c = 0; c < components(node.type); ++c) {
            const float* a = in(0, c);
            const float* b = in(1, c);
            const bool aUniform = uniformLanes(node.operands[0], c), bUniform = uniformLanes(node.operands[1], c);
            float* out = floats(index, c);
            if (plan.op == RowOp::Add) binary<Add>(a, aUniform, b, bUniform, out, count);
            else if (plan.op == RowOp::Subtract) binary<Subtract>(a, aUniform, b, bUniform, out, count);
            else if (plan.op == RowOp::Multiply) binary<Multiply>(a, aUniform, b, bUniform, out, count);
            else binary<Divide>(a, aUniform, b, bUniform, out, count);
        }
        return;
    case RowOp::Fractal: {
        const uint32_t position = node.operands[0];
        const std::vector<Value>& uniform = scalar_.values();
        const bool perlin = node.operands.size() == 2;
        const int32_t octaves = perlin ? 1 : uniform[node.operands[1]].i;
        const float lacunarity = perlin ? 1.0f : uniform[node.operands[2]].v.x;
        const float gain = perlin ? 1.0f : uniform[node.operands[3]].v.x;
        const uint32_t seed = uint32_t(uniform[node.operands.back()].i);
        fractal_.evaluate(plan.fold, floats(position, 0), floats(position, 1)[0], floats(position, 2)[0], octaves,
                          lacunarity, gain, seed, size_t(count), floats(index, 0));
        return;
    }
    case RowOp::Lanes: {
        const FunctionInfo* function = node.kind == FieldNode::Kind::Call ? &functions()[node.function] : nullptr;
        for (int i = 0; i < count; ++i) {
            const glm::ivec3 local = first + glm::ivec3(i, 0, 0);
            arguments_.clear();
            for (uint32_t operand : node.operands) arguments_.push_back(laneValue(operand, i));
            storeLane(index, i, nodeValue(node, function, arguments_, glm::vec3(localBase_ + local), origin_ + local));
        }
        return;
    }
    }
}

void FieldRowEvaluator::evaluate(glm::ivec3 first, int count, float* out) {
    VOXC_ASSERT(count > 0 && count <= kRowVoxels);
    const glm::vec3 position(localBase_ + first);
    const glm::ivec3 world = origin_ + first;
    if (writesRoot_) lanes_[size_t(field_.root) * 3] = out;
    for (uint32_t i = 0; i < plans_.size(); ++i) {
        const NodePlan& plan = plans_[i];
        if (plan.constant) continue;
        if (plan.scalar) scalar_.evaluateNode(i, position, world);
        if (plan.readAsLanes) storeUniform(i);
        if (!plan.uniform) evaluateVarying(i, first, count);
    }
    if (plans_[field_.root].uniform) std::fill_n(out, count, scalar_.values()[field_.root].v.x);
    else if (!writesRoot_) std::copy_n(floats(field_.root, 0), count, out);
}

} // namespace voxc

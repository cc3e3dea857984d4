#pragma once
// Field stages on the CPU: a field's DAG evaluated per voxel with the builtin registry's
// `eval`, combined with the grid's density by the stage's FieldMode.
#include "voxc/builtins/Functions.h"
#include "voxc/grid/Grid.h"
#include "voxc/grid/NonFinite.h"
#include "voxc/program/Program.h"

#include <functional>
#include <span>
#include <glm/vec3.hpp>
#include <vector>

namespace voxc {

// Evaluates one field at voxels, reusing its buffers: no allocation per voxel.
class FieldEvaluator {
public:
    // `localBase`: World::localBase, the file's grid-local coordinate of grid voxel (0,0,0).
    FieldEvaluator(const Field& field, glm::ivec3 origin, glm::ivec3 localBase = glm::ivec3(0));

    // The value of every node at grid voxel `local` (inputs: x = float(localBase.x + local.x),
    // wx = float(origin.x + local.x), ...); the root's value is `values()[field.root]`.
    const std::vector<Value>& evaluate(glm::ivec3 local);
    float density(glm::ivec3 local) { return evaluate(local)[field_.root].v.x; }
    // The field with inputs x, y, z = `position` and wx, wy, wz = float(`world`): a stamp's frame
    // (voxc::stampLocal) at the world voxel it writes.
    const std::vector<Value>& evaluateAt(glm::vec3 position, glm::ivec3 world);
    // Node `node` alone, from its operands' values as the last evaluations left them.
    void evaluateNode(size_t node, glm::vec3 position, glm::ivec3 world);
    const std::vector<Value>& values() const { return values_; }

private:
    const Field& field_;
    glm::ivec3 origin_;
    glm::ivec3 localBase_;
    std::vector<const FunctionInfo*> functions_; // per node, Call nodes only
    std::vector<Value> values_;
    std::vector<Value> arguments_;
};

// One node's value from its operands' values (in the node's operand order); `function` is the
// node's builtin when it is a Call.
Value nodeValue(const FieldNode& node, const FunctionInfo* function, std::span<const Value> operands,
                glm::vec3 position, glm::ivec3 world);

// Runs one field stage over the whole grid in place: voxc::combineField at every voxel with the
// field's value, or with 0 where that value is not finite (counted in `nonFinite` when set).
// `progress`, when set, is called before each z slice with the fraction done (InterpOptions::progress).
void runField(const Program& program, const Stage& stage, DenseGrid& grid, NonFiniteCount* nonFinite = nullptr,
              const std::function<void(double)>& progress = {});

} // namespace voxc

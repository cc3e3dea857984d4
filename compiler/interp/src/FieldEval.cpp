#include "voxc/interp/FieldEval.h"

#include "voxc/interp/FieldRows.h"

#include "voxc/program/Semantics.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

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
    for (size_t i = 0; i < field_.nodes.size(); ++i) evaluateNode(i, position, world);
    return values_;
}

void FieldEvaluator::evaluateNode(size_t node, glm::vec3 position, glm::ivec3 world) {
    arguments_.clear();
    for (uint32_t operand : field_.nodes[node].operands) arguments_.push_back(values_[operand]);
    values_[node] = nodeValue(field_.nodes[node], functions_[node], arguments_, position, world);
}

Value nodeValue(const FieldNode& node, const FunctionInfo* function, std::span<const Value> operands,
                glm::vec3 position, glm::ivec3 world) {
    switch (node.kind) {
    case FieldNode::Kind::Constant: return constantValue(node);
    case FieldNode::Kind::Input: {
        const int axis = int(node.input) % 3;
        const bool isWorld = node.input >= FieldInput::WorldX;
        return Value::makeFloat(isWorld ? float(world[axis]) : position[axis]);
    }
    case FieldNode::Kind::Component: return Value::makeFloat(operands[0].v[int(node.component)]);
    case FieldNode::Kind::PointSet: // the lists binned at check time; any lists give the same floats
        return Value::makeVec2(pointSetDistances(*node.pointSet, node.pointSet->bins, operands[0].v));
    case FieldNode::Kind::Map:
        return Value::makeFloat(node.map->dimensions == 2
                                    ? sampleMap(*node.map, operands[0].v.x, operands[1].v.x)
                                    : sampleVolume(*node.map, operands[0].v.x, operands[1].v.x, operands[2].v.x));
    case FieldNode::Kind::Call: return function->eval(operands);
    }
    throw InternalError("a field node of unknown kind");
}

void runField(const Program& program, const Stage& stage, DenseGrid& grid, NonFiniteCount* nonFinite,
              const std::function<void(double)>& progress) {
    VOXC_ASSERT(stage.kind == Stage::Kind::Field && stage.index < program.fields.size());
    VOXC_ASSERT(grid.size() == program.world.size);
    const glm::ivec3 size = grid.size();
    // Each of the host's threads takes a slab of z slices (consecutive slices share noise
    // lattice cells, voxc::FractalRow); no voxel's value or combination depends on which thread
    // made it, and the replacements are summed, so the grid is the same however many run.
    const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(size.z, 1));
    std::atomic<int> doneSlices{0};
    std::atomic<bool> stop{false};
    std::vector<NonFiniteCount> replaced(static_cast<size_t>(threads));
    const bool setsDensityOnly = stage.mode == FieldMode::Set && !stage.material;
    const auto work = [&](int thread) {
        FieldRowEvaluator evaluator(program.fields[stage.index], program.world.origin, program.world.localBase);
        float row[FieldRowEvaluator::kRowVoxels];
        const int z1 = int(int64_t(size.z) * (thread + 1) / threads);
        for (int z = int(int64_t(size.z) * thread / threads); z < z1 && !stop; ++z) {
            if (thread == 0 && progress) progress(double(doneSlices) / double(size.z));
            for (int y = 0; y < size.y; ++y)
                for (int x0 = 0; x0 < size.x; x0 += FieldRowEvaluator::kRowVoxels) {
                    const int count = std::min(FieldRowEvaluator::kRowVoxels, size.x - x0);
                    const size_t first = grid.index({x0, y, z});
                    float* densities = grid.data().data() + first;
                    if (setsDensityOnly) { // combineField's set without a material: d = f
                        evaluator.evaluate({x0, y, z}, count, densities);
                        replaced[size_t(thread)].replaceRow(densities, count, first);
                        continue;
                    }
                    evaluator.evaluate({x0, y, z}, count, row);
                    replaced[size_t(thread)].replaceRow(row, count, first);
                    combineFieldRow(stage.mode, stage.material, row, count, densities, grid.materials().data() + first);
                }
            ++doneSlices;
        }
    };
    std::vector<std::thread> helpers;
    std::exception_ptr failed;
    std::mutex failedMutex;
    const auto guarded = [&](int thread) {
        try {
            work(thread);
        } catch (...) {
            stop = true;
            const std::lock_guard lock(failedMutex);
            if (!failed) failed = std::current_exception();
        }
    };
    for (int t = 1; t < threads; ++t) helpers.emplace_back(guarded, t);
    guarded(0);
    for (std::thread& helper : helpers) helper.join();
    if (failed) std::rethrow_exception(failed);
    if (nonFinite)
        for (const NonFiniteCount& count : replaced)
            if (count.count > 0) {
                if (nonFinite->count == 0 || count.firstIndex < nonFinite->firstIndex) nonFinite->firstIndex = count.firstIndex;
                nonFinite->count += count.count;
            }
}

} // namespace voxc

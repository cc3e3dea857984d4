#include "voxc/ir/passes/ClassifyFieldChunks.h"

#include "voxc/builtins/Functions.h"
#include "voxc/builtins/Intervals.h"

#include <glm/common.hpp>

#include <algorithm>

namespace voxc::ir {

namespace {

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

} // namespace

std::vector<Interval> fieldNodeIntervals(const IrField& field, const std::array<Interval, 6>& inputs) {
    std::vector<Interval> values(field.nodes.size());
    std::vector<Interval> args;
    for (size_t i = 0; i < field.nodes.size(); ++i) {
        const FieldNode& node = field.nodes[i];
        switch (node.kind) {
        case FieldNode::Kind::Constant:
            values[i] = node.type == Type::Int    ? Interval::point(Type::Int, glm::dvec3(node.constantInt, 0, 0))
                        : node.type == Type::Bool ? Interval::point(Type::Bool, glm::dvec3(node.constantBool, 0, 0))
                                                  : Interval::point(node.type, glm::dvec3(node.constant));
            break;
        case FieldNode::Kind::Input: values[i] = inputs[int(node.input)]; break;
        case FieldNode::Kind::Component: {
            const Interval& v = values[node.operands[0]];
            const int c = int(node.component);
            values[i] = {Type::Float, {v.lo[c], 0, 0}, {v.hi[c], 0, 0}, v.exact};
            break;
        }
        case FieldNode::Kind::PointSet: {
            // Each distance is capped at its reach: exactly the reach where nothing reaches the box.
            const Interval& p = values[node.operands[0]];
            const PointSet& set = *node.pointSet;
            const glm::bvec2 reaches = pointSetReaches(set, p.lo, p.hi);
            const glm::dvec3 cap(set.centreReach, set.segmentReach, 0.0);
            values[i] = {Type::Vec2, {reaches.x ? 0.0 : cap.x, reaches.y ? 0.0 : cap.y, 0.0}, cap,
                         !reaches.x && !reaches.y};
            break;
        }
        case FieldNode::Kind::Map: {
            MapRange range{};
            if (node.map->dimensions == 2) {
                const Interval& x = values[node.operands[0]];
                const Interval& z = values[node.operands[1]];
                range = mapRange(*node.map, x.lo.x, x.hi.x, z.lo.x, z.hi.x);
            } else {
                double lo[3], hi[3];
                for (int a = 0; a < 3; ++a) lo[a] = values[node.operands[a]].lo.x, hi[a] = values[node.operands[a]].hi.x;
                range = volumeRange(*node.map, lo, hi);
            }
            values[i] = {Type::Float, {range.lo, 0, 0}, {range.hi, 0, 0}, false};
            break;
        }
        case FieldNode::Kind::Call: {
            const RangeRule rule = rangeRule(functions()[node.function].name);
            if (!rule) {
                values[i] = Interval::unknown(node.type);
                break;
            }
            args.clear();
            for (uint32_t o : node.operands) args.push_back(values[o]);
            values[i] = rule(args);
            break;
        }
        }
    }
    return values;
}

namespace {

// The root's interval over positions localMin <= local < localMax.
Interval rootInterval(const World& world, const IrField& field, glm::ivec3 localMin, glm::ivec3 localMax) {
    std::array<Interval, 6> inputs;
    for (int input = 0; input < 6; ++input) {
        const int axis = input % 3;
        const int shift = input >= int(FieldInput::WorldX) ? world.origin[axis] : world.localBase[axis];
        // The evaluator converts the integer coordinate to float: monotone, so the
        // converted ends bound every converted coordinate (even past 2^24).
        const double lo = double(float(int64_t(localMin[axis]) + shift));
        const double hi = double(float(int64_t(localMax[axis]) - 1 + shift));
        inputs[input] = {Type::Float, {lo, 0, 0}, {hi, 0, 0}, lo == hi};
    }
    return fieldNodeIntervals(field, inputs)[field.root];
}

} // namespace

std::vector<FieldChunk> classifyFieldChunks(const World& world, const IrField& field) {
    const int size = world.chunkSize;
    glm::ivec3 first, last; // world chunk coordinates, inclusive
    for (int c = 0; c < 3; ++c) {
        first[c] = floorDiv(world.origin[c], size);
        last[c] = floorDiv(world.origin[c] + world.size[c] - 1, size);
    }
    std::vector<FieldChunk> chunks;
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                FieldChunk chunk;
                chunk.chunk = {x, y, z};
                chunk.localMin = glm::max(chunk.chunk * size - world.origin, glm::ivec3(0));
                chunk.localMax = glm::min((chunk.chunk + 1) * size - world.origin, world.size);
                const Interval root = rootInterval(world, field, chunk.localMin, chunk.localMax);
                if (root.type == Type::Float) chunk.lo = root.lo.x, chunk.hi = root.hi.x;
                if (root.type == Type::Float && root.exact) {
                    chunk.constant = true;
                    chunk.value = float(root.lo.x);
                }
                chunks.push_back(chunk);
            }
    return chunks;
}

} // namespace voxc::ir

#pragma once
// A field on the host a row of voxels along x at a time, for field stages (voxc::runField).
// A node whose every component is the same along the row (it does not depend on x) is evaluated
// once per row by FieldEvaluator; arithmetic and vector construction run as loops over the row;
// fbm, turbulence, ridged and perlin3 of a position whose y and z are the same along the row run
// through FractalRow (voxc/builtins/NoiseRow.h); any other node voxel by voxel through its
// record's `eval`. Every voxel's value equals FieldEvaluator's bit for bit (tests/interp FieldRows).
#include "voxc/builtins/NoiseRow.h"
#include "voxc/interp/FieldEval.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace voxc {

class FieldRowEvaluator {
public:
    static constexpr int kRowVoxels = 256;

    // As FieldEvaluator's: `localBase` is the file's grid-local coordinate of grid voxel (0,0,0).
    FieldRowEvaluator(const Field& field, glm::ivec3 origin, glm::ivec3 localBase = glm::ivec3(0));

    // out[i] = the field's value at grid voxel first + (i, 0, 0), for i < count <= kRowVoxels.
    void evaluate(glm::ivec3 first, int count, float* out);

private:
    // How a node that varies along the row is evaluated.
    enum class RowOp : uint8_t { InputX, Component, Add, Subtract, Multiply, Divide, Negate, Construct, Fractal, Lanes };

    struct NodePlan {
        bool varies[3] = {false, false, false}; // per component: differs along the row
        bool uniform = true;                     // no component varies
        bool constant = false;                   // a Constant: evaluated (and stored as lane 0) once
        bool scalar = false;                     // evaluated once per row by scalar_
        bool readAsLanes = false;                // uniform, read (as lane 0) by a varying node
        RowOp op = RowOp::Lanes;
        FractalFold fold = FractalFold::Sum;
    };

    float* floats(uint32_t node, int component) { return lanes_[size_t(node) * 3 + size_t(component)]; }
    // Whether component `component` of node's lanes is its lane 0 alone: the same along the row
    // (a float's one component for any). Every reader takes lane 0 of such a component.
    bool uniformLanes(uint32_t node, int component) const;
    Value laneValue(uint32_t node, int lane);
    void storeLane(uint32_t node, int lane, const Value& value);
    void storeUniform(uint32_t node); // a uniform node's value as its lane 0
    void evaluateVarying(uint32_t node, glm::ivec3 first, int count);

    const Field& field_;
    glm::ivec3 origin_;
    glm::ivec3 localBase_;
    FieldEvaluator scalar_;
    std::vector<NodePlan> plans_;
    std::vector<float> floats_;  // [node][component][lane] of nodes of float types
    std::vector<float*> lanes_;  // [node][component]: where its lanes are (its own, an operand's, the caller's row)
    bool writesRoot_ = false;    // the root writes straight into evaluate's `out`
    std::vector<int32_t> ints_;  // [node][lane]
    std::vector<uint8_t> bools_; // [node][lane]
    std::vector<Value> arguments_;
    FractalRow fractal_;
};

} // namespace voxc

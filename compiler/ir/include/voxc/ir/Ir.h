#pragma once
// The IR: what the kernels of one program must do, in execution order (grammar sweeps and
// field expressions).
// Lowering fills it from a checked Program; the passes in voxc/ir/passes refine it; codegen
// turns each sweep into one compute kernel. printIr gives a stable text form for tests and
// `voxc compile --print-ir`.
#include "voxc/program/Program.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::ir {

// What a kernel must do with one window cell. Lowering starts every cell at Load; the
// dead-cells pass narrows it to what the live rules need.
enum class CellAccess : uint8_t {
    None,    // no live rule reads or writes the cell
    Address, // written without reading the old density (SET, `MAT m`), or only its material is read
    Load,    // a predicate or a transform reads the density
};

struct IrCell {
    glm::ivec3 offset{0}; // position inside the window
    CellAccess access = CellAccess::Load;
    // A live rule tests the cell's material (MAT/NMAT), so the kernel loads it beside the
    // density. Set by the dead-cells pass.
    bool loadsMaterial = false;
    // Distinct non-IGN predicates the live rules test on this cell; bit i of the cell's
    // pass mask is tests[i]. Empty until the predicate-bits pass runs.
    std::vector<Predicate> tests;
    // Distinct material tests, numbered after the density tests: bit tests.size() + i of the
    // pass mask is materialTests[i].
    std::vector<MaterialPredicate> materialTests;
};

// Bits of a cell's pass mask: density tests, then material tests.
inline uint32_t testCount(const IrCell& cell) { return uint32_t(cell.tests.size() + cell.materialTests.size()); }

struct IrRule {
    uint32_t ruleIndex = 0; // index into Grammar::rules, stable across passes
    std::string name;
    SourceLoc loc;
    int32_t priority = 0;
    uint32_t weightUnits = 1000;
    uint32_t probabilityUnits = kProbabilityOne;
    std::vector<SymbolCell> symbol;       // per window cell, cellIndex order
    std::vector<TransformCell> transform; // per window cell, cellIndex order
    std::vector<AggregateTest> aggregates; // tested after the cells, in order (Aggregates.h)
    std::vector<Stamp> stamps;             // applied by the sweep's stamp kernel after each phase
    // Per window cell: bits of the cell's pass mask (IrCell::tests, then materialTests) that must all pass. Filled by the
    // predicate-bits pass (one entry per cell); empty before.
    std::vector<std::vector<uint32_t>> needs;
};

// A rule some pass proved can never match; kept so the generated code can say why it is absent.
struct IrRemovedRule {
    uint32_t ruleIndex = 0;
    std::string name;
    SourceLoc loc;
    uint32_t cell = 0; // a window cell whose predicates no density passes
};

struct IrSweep {
    uint32_t index = 0; // position in the grammar's execution order; the anchor hash's sweep input
    glm::ivec3 window{1};
    glm::ivec3 anchorCount{0}; // as voxc::Sweep
    glm::ivec3 phaseCount{1};
    std::vector<IrCell> cells; // every window cell, cellIndex order
    std::vector<IrRule> rules; // live rules, declaration order
    std::vector<IrRemovedRule> removed;
};

struct IrGrammar {
    std::string name;
    SourceLoc loc;
    uint32_t programIndex = 0; // index into Program::grammars
    glm::ivec3 stride{1};
    glm::ivec3 boundsMin{0};
    glm::ivec3 boundsMax{0};
    int32_t iterations = 1;
    std::optional<float> clampMin;
    std::optional<float> clampMax;
    std::vector<IrSweep> sweeps; // execution order
};

// A field expression as the kernels evaluate it. Lowering copies Program::fields; the field
// passes fold, share and hoist its nodes (still topological: operands precede users).
struct IrField {
    std::string name;
    SourceLoc loc;
    std::vector<FieldNode> nodes;
    uint32_t root = 0;
    // Per node: true when it does not depend on y (LocalY/WorldY), so a column-walking kernel
    // computes it once per (x, z) column. Empty until the hoist-column-values pass runs.
    std::vector<bool> perColumn;
};

struct IrModule {
    std::string sourcePath;
    World world;
    std::vector<StartShape> start;
    std::vector<IrGrammar> grammars; // Program::grammars order
    std::vector<IrField> fields;     // Program::fields order; a Field stage's index points here
    std::vector<Stage> pipeline;     // the stages that run
    // Stages removed because a later stage overwrites everything they wrote; printed only.
    std::vector<Stage> deadStages;
};

// "set", "union", "subtract", "intersect", "paint": the pipeline keyword and kernel-name suffix.
std::string_view fieldModeName(FieldMode mode);

// Window cell position of a cellIndex.
glm::ivec3 cellOffset(glm::ivec3 window, uint32_t cell);

// Stable, human-readable text of the whole module.
std::string printIr(const IrModule& module);

// The pieces printIr uses, shared with the comments of generated code:
// "GEQ 0.5", "MAT 2", "ADD -0.5 & MAT 2", "(1, 0, 2)", "[3, 3, 1]" (materials by id).
std::string printPredicate(const Predicate& predicate);
std::string printMaterialPredicate(const MaterialPredicate& predicate);
std::string printAggregate(const AggregateTest& test); // "solid cells over [0, 0, 0]..[3, 1, 3]: 5 to 9"
std::string printTransform(const TransformCell& transform);
std::string printCell(glm::ivec3 offset);
std::string printVec(glm::ivec3 v);
// "start", a grammar's name, "set ground" or "paint low material 2".
std::string printStage(const Stage& stage);

} // namespace voxc::ir

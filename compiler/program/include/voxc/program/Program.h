#pragma once
// The checked program: what the checker produces from a .vox file once every name is
// resolved, every value is in range and every array has its declared shape. The interpreter
// and the IR lowering both start from here; neither ever sees the AST.
#include "voxc/core/SourceLoc.h"
#include "voxc/program/Aggregates.h"
#include "voxc/program/Field.h"
#include "voxc/program/SolveTable.h"
#include "voxc/program/Speleothems.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace voxc {

enum class SymbolOp : uint8_t { IGN, PRES, ABS, EQ, NEQ, LT, LEQ, GT, GEQ };
enum class TransformOp : uint8_t { NOP, SET, ADD };

struct Predicate {
    SymbolOp op = SymbolOp::IGN;
    float value = 0.0f; // unused by IGN, PRES, ABS
};

// Materials: every voxel carries an 8-bit material id beside its density. Id 0 is the builtin
// `none` (every voxel's material before anything writes one); declared materials use 1..255.
constexpr uint8_t kMaterialNone = 0;

// Tests of a cell's material: MAT m passes when the material is m, NMAT m when it is not.
enum class MaterialOp : uint8_t { MAT, NMAT };
struct MaterialPredicate {
    MaterialOp op = MaterialOp::MAT;
    uint8_t material = kMaterialNone;
};

// A symbol cell passes when every predicate passes (density and material alike); a cell with
// neither is IGN.
struct SymbolCell {
    std::vector<Predicate> predicates;
    std::vector<MaterialPredicate> materialPredicates;
};

struct TransformCell {
    TransformOp op = TransformOp::NOP;
    float value = 0.0f; // unused by NOP
    // `& MAT m` in a transform cell: the cell's material becomes m (after any density write).
    std::optional<uint8_t> material;
};

// Cells of a window are stored x fastest, then y (up), then z:
// index = x + I * (y + J * z). The checker converts from the printed layout
// (first written row = top = highest y).
inline int cellIndex(glm::ivec3 size, int x, int y, int z) { return x + size.x * (y + size.y * z); }

// Weights are fixed point so tie-breaking is integer arithmetic on every device.
constexpr float kWeightUnitsPerOne = 1000.0f;   // weight 1.0 == 1000 units; range (0, 1000]
constexpr uint32_t kProbabilityOne = 1u << 24;  // probability 1.0 == 2^24

// How a field stage combines the field's value f with the grid's density d at each voxel.
// Densities follow the grammar's convention (1 rock, 0 air). The material rule is
// voxc::combineField (Semantics.h).
enum class FieldMode : uint8_t {
    Set,       // d = f
    Union,     // d = max(d, f): add rock
    Subtract,  // d = min(d, 1 - f): carve rock away
    Intersect, // d = min(d, f)
    Paint      // d unchanged; only writes the stage's material (which it requires)
};

// A rule's stamp (Dey §5.3.2, feature transforms): where the rule fires, the field its block
// names (`stamp NAME { ... }`) is combined into the grid like a field stage, evaluated in the stamp's own frame and
// written only inside the window grown by `reach` (docs/language.md, "Stamps"). A variant made
// by `symmetry` keeps the written rule's frame: its variant axis i reads written axis from[i],
// mirrored when negate[i], so the stamp turns with the window.
struct Stamp {
    std::string fieldName;        // as written, for traces and generated code
    uint32_t field = 0;           // index into Program::fields
    SourceLoc loc;                // the field's name in the stamp block
    FieldMode mode = FieldMode::Union;
    std::optional<uint8_t> material; // written where the field wins (combineField)
    glm::vec3 offset{0.0f};       // the stamp's origin, in the written rule's window cells
    glm::ivec3 reach{0};          // per variant axis: writes anchor - reach <= v < anchor + window + reach
    glm::ivec3 writtenSize{1};    // the written rule's window
    glm::ivec3 from{0, 1, 2};
    glm::bvec3 negate{false};
};

// The stamp's field inputs x, y, z at a voxel `fromAnchor` cells from the variant's anchor: the
// voxel's cell in the written window's axes, as an integer, converted once, minus the offset.
inline glm::vec3 stampLocal(const Stamp& stamp, glm::ivec3 fromAnchor) {
    glm::ivec3 written(0);
    for (int axis = 0; axis < 3; ++axis) {
        const int from = stamp.from[axis];
        written[from] = stamp.negate[axis] ? stamp.writtenSize[from] - 1 - fromAnchor[axis] : fromAnchor[axis];
    }
    return glm::vec3(written) - stamp.offset;
}

struct Rule {
    std::string name;
    SourceLoc loc;
    glm::ivec3 size{1, 1, 1};
    std::vector<SymbolCell> symbol;       // size.x*size.y*size.z cells
    std::vector<TransformCell> transform; // same count
    int32_t priority = 0;
    float weight = 1.0f;
    float probability = 1.0f;
    uint32_t weightUnits = 1000;                 // round(weight * kWeightUnitsPerOne), >= 1
    uint32_t probabilityUnits = kProbabilityOne; // round(probability * kProbabilityOne)
    std::vector<AggregateTest> aggregates;       // `where` blocks: all must pass, with the symbol
    std::vector<Stamp> stamps;                   // applied after the phase's transforms, in order
};

struct Grammar {
    std::string name;
    SourceLoc loc;
    glm::ivec3 stride{1, 1, 1};
    glm::ivec3 boundsMin{0, 0, 0}; // grid-local, half-open, already clipped to the grid
    glm::ivec3 boundsMax{0, 0, 0};
    // The anchor at boundsMin is number firstAnchor of the declared bounds' anchors (per axis):
    // 0, except in a region grid (voxc/stages/Region.h) that starts past the declared bounds'
    // min, so phases stay the declared ones (n mod ceil(size / stride) of the declared n).
    glm::ivec3 firstAnchor{0, 0, 0};
    int32_t iterations = 1;
    std::optional<float> clampMin; // clamp applies to every value a transform writes
    std::optional<float> clampMax;
    std::vector<Rule> rules;       // declaration order
};

enum class ShapeKind : uint8_t { Fill, Box, Sphere, Wall, HalfSpace, Heightfield };

// Parameters of the start state's 3-octave (by default) Perlin heightfield (Dey §3.2).
struct HeightfieldParams {
    float base = 16.0f;       // mean surface height in voxels
    float amplitude = 8.0f;   // height of the first octave in voxels
    float frequency = 0.03f;  // first octave, cycles per voxel (world coordinates)
    int32_t octaves = 3;
    float lacunarity = 2.0f;
    float gain = 0.5f;
};

// One statement of the start block; later shapes overwrite earlier ones where they are solid.
// Positions are grid-local voxel coordinates; a voxel is sampled at its integer index.
struct StartShape {
    ShapeKind kind = ShapeKind::Fill;
    SourceLoc loc{};
    float value = 1.0f;             // density written inside the shape (Fill: everywhere)
    glm::vec3 min{0.0f}, max{0.0f}; // Box: min <= p < max
    glm::vec3 center{0.0f};         // Sphere: |p - center| <= radius
    float radius = 0.0f;
    int32_t axis = 0;               // Wall: at <= p[axis] < at + thickness
    float at = 0.0f;
    float thickness = 1.0f;
    glm::vec3 normal{0.0f, 1.0f, 0.0f}; // HalfSpace: dot(p, normal) <= offset
    float offset = 0.0f;
    HeightfieldParams heightfield{}; // Heightfield: p.y < height(world x, world z)
    std::optional<uint8_t> material{}; // written wherever the shape writes its value; absent: untouched
};

struct World {
    glm::ivec3 size{64, 64, 64};
    glm::ivec3 origin{0, 0, 0}; // world coordinate of grid voxel (0,0,0)
    // The file's grid-local coordinate of grid voxel (0,0,0): 0 for the declared grid; a region
    // grid's corner inside it otherwise (voxc/stages/Region.h). Positions a file writes in grid-local
    // voxels (start shapes, x/y/z, features) are grid index + localBase, so a region computes what
    // the declared grid computes there.
    glm::ivec3 localBase{0, 0, 0};
    int32_t chunkSize = 32;     // power of two, 8..64
    uint32_t seed = 0;
    // `size = [unbounded, Y, unbounded]`: x and/or z declared without end. Such an axis has the
    // largest size (2^20 voxels from the origin); only a box of the world can run (--region).
    glm::bvec3 unbounded{false};
};

// One step of the pipeline. Each kind is one record in compiler/stages (StageKind.h) holding
// its checks, interpretation and lowering; passes read the facts below instead of the kind.
struct Stage {
    enum class Kind : uint8_t { Start, Grammar, Field, Curves, Speleothems };
    Kind kind = Kind::Start;
    uint32_t index = 0;               // into Program::grammars, Program::fields or Program::speleothems
    FieldMode mode = FieldMode::Set;  // Field only
    SourceLoc loc{};
    // Field only: the material written where the field wins (combineField); from the stage's
    // `material NAME` clause, else the feature's `material` key; absent: materials untouched.
    std::optional<uint8_t> material{};
    // Filled from the kind's record (stages::makeStage, stages::describePipeline):
    std::string label{};         // the pipeline entry as written: "start", "erode", "subtract tunnel"
    bool readsDensities = true;  // the result depends on the densities before the stage
    bool writesMaterials = true; // the stage may write a material id
};

// A declared material: `material rock { id = 1; color = [0.45, 0.42, 0.4]; }`.
struct Material {
    std::string name;
    SourceLoc loc;
    uint8_t id = 1;                         // 1..255, unique
    glm::vec3 color{0.6f, 0.6f, 0.6f};      // linear RGB in [0, 1], for mesh export
};

// A file a `heightmap` or `mesh` block reads (docs/language.md, "Input files"): tracked by the
// depfile, copied into a compiled package with its SHA-256, served back to the check when the
// package is loaded.
struct InputFile {
    std::string block;  // the block's name
    std::string kind;   // "heightmap" or "mesh"
    std::string name;   // the `file` string as written (relative to the .vox's folder, or absolute)
    std::string path;   // as the checker opened it (the name joined to the .vox's folder)
    std::shared_ptr<const std::string> bytes; // what was read
    SourceLoc loc;      // the `file` value
    bool outside = false; // absolute, or leaving the .vox's folder through `..`
};

struct Program {
    std::string sourcePath;
    World world;
    std::vector<StartShape> start; // empty means all air
    std::vector<Grammar> grammars;
    std::vector<Field> fields;     // named density fields, declaration order
    std::vector<Stage> pipeline;   // Start first, then grammars and field stages in pipeline order
    std::vector<SpeleothemStage> speleothems; // declared speleothem features, declaration order
    std::vector<CurvesBlock> curves; // declared curves blocks with their solved tables, declaration order
    std::vector<Material> materials; // declared materials, declaration order (`none` is implicit)
    std::vector<InputFile> inputs;   // heightmap and mesh files, declaration order

    // True when anything reads or writes a material: only then do backends store the channel
    // (a program without materials leaves every voxel `none`).
    bool usesMaterials() const;
    // The declared material with this id, or nullptr (id 0 and undeclared ids).
    const Material* findMaterial(uint8_t id) const;
};

// Limits enforced by the checker so a bad file fails with a message, not an OOM kill, a stack
// overflow or a run of hours. docs/language.md ("Limits") lists each with its error code.
struct Limits {
    int64_t maxVoxels = int64_t(512) * 512 * 512;
    int32_t maxIterations = 100000;
    int32_t maxWindowCells = 512;
    int32_t maxRulesPerSweep = 256;
    // Rules x window cells of one sweep: the size of its generated kernel; tests per symbol cell.
    int64_t maxSweepRuleCells = 4096;
    int32_t maxCellTerms = 32;
    // A stamp's reach per axis, and the windows of one phase whose grown boxes may cover one voxel
    // (each voxel of a stamp pass folds over that many anchors).
    int32_t maxStampReach = 64;
    int64_t maxStampOverlap = 512;
    int32_t maxStartShapes = 256;
    // One generated kernel: the field DAG nodes it holds (a sweep's stamp kernel holds the fields
    // of all its stamps; a field kernel one field, bounded by maxFieldNodes), and the loop
    // iterations one invocation may take. lavapipe (llvmpipe) counts the iterations of all loops
    // of an invocation group together and, past 65,535, silently leaves every loop: a kernel that
    // could loop more would compute a wrong result, so the checker refuses it.
    int64_t maxKernelFieldNodes = 100000;
    int64_t maxKernelLoopIterations = 65535;
    int64_t maxSourceBytes = int64_t(4) << 20;
    // Depth of the parse tree: brackets, blocks, unary operators, `let`, `?:` and operator chains.
    int32_t maxNesting = 256;
    // Expression nodes lowering one field or function may visit, a function counting once per
    // distinct argument list.
    int64_t maxLoweringSteps = 1000000;
    int32_t maxParameters = 64; // of one user function
    // A field's DAG after inlining: nodes, and the longest operand chain (also the deepest
    // expression nesting, counted through inlined calls, that lowering accepts).
    int32_t maxFieldNodes = 100000;
    int32_t maxFieldDepth = 1024;
    // Distinct kernels the pipeline needs (field stages of a new field, mode or material; sweeps
    // of a grammar not run before): compiling each costs milliseconds.
    int64_t maxKernels = 512;
    // Estimated work of the whole pipeline (see docs/language.md, "Work estimate"); `--max-work`.
    int64_t maxWork = int64_t(100) * 1000 * 1000 * 1000;
    // Host solves: the cells of all curves boxes (each about 3 us to solve), the voxelised cells
    // of all terrain blocks (a height lookup each, 8 bytes of table: 512 MiB at the limit), and
    // one terrain block's cell updates (diffusion sweeps plus erosion steps, about 20-100 million
    // a second).
    int64_t maxSolveCells = 8'388'608; // 256 x 128 x 256
    int64_t maxTerrainCells = 67'108'864; // 512 x 256 x 512
    int64_t maxTerrainWork = int64_t(2) * 1000 * 1000 * 1000;
    // Files heightmap and mesh blocks read (docs/language.md, "Heightmaps", "Meshes"): the bytes
    // of one file, a height image's pixels, a mesh's vertices and triangles, a mesh's
    // signed-distance grid, and the cells of all their maps together (uploaded beside the grid).
    int64_t maxInputBytes = int64_t(256) << 20;
    int64_t maxImagePixels = int64_t(4096) * 4096;
    int64_t maxMeshTriangles = 2'000'000;
    int64_t maxMeshPoints = 2'000'000;
    int64_t maxDistanceCells = int64_t(256) * 256 * 256;
    int64_t maxMapCells = int64_t(32) << 20;
};

} // namespace voxc

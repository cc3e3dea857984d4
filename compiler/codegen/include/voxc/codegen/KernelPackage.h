#pragma once
// What the compiler hands the runtime: generated kernels plus the plan that orders their
// dispatches. `voxc compile` writes it out as GLSL + SPIR-V files and manifest.json.
#include "voxc/program/Program.h"
#include "voxc/program/Semantics.h"
#include "voxc/program/SolveTable.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voxc {

// The push-constant block every kernel declares (compiler/shaders/common.glsl), std430 layout.
// The runtime fills one per dispatch.
struct PushBlock {
    int32_t gridOrigin[4];  // xyz: world coordinate of grid voxel (0,0,0); w: chunk size
    int32_t gridSize[4];    // xyz: grid size in voxels; w: seed (bit pattern)
    int32_t chunkBase[4];   // xyz: world chunk coordinate of chunk-table entry 0; w: iteration
    int32_t chunkCount[4];  // xyz: chunk-table extents; w: sweep index within its grammar
    int32_t anchorStart[4]; // xyz: grid-local first anchor (start kernel: 0); w: active-dispatch record
                            // (field kernel: the constant box's float bits)
    int32_t anchorStep[4];  // xyz: distance between anchors of one phase (start kernel: 1; stamp kernel: the
                            // phase's first anchor); w: log2 tile size
    int32_t anchorCount[4]; // xyz: anchors per axis in this dispatch (start kernel: grid size);
                            // w: 1 when the sweep runs indirectly over the active tiles, else 0
                            // (field kernel: 1 in a constant box)
};
static_assert(sizeof(PushBlock) == 112, "must match common.glsl");

// Descriptor set 0 for every kernel.
constexpr uint32_t kBindingVoxels = 0;     // buffer of float densities, chunk-major (see runtime ChunkLayout)
constexpr uint32_t kBindingChunkTable = 1; // buffer of int: chunk-table entry -> chunk slot
constexpr uint32_t kBindingNoiseTables = 2; // buffer of int: Perlin's 256-entry permutation (voxc::perlinPermutation)
// Tile skipping (compiler/shaders/tiles.glsl): a tile is a world-aligned cube of 2^anchorStep.w
// voxels per axis inside one chunk, chosen by the runtime; buffers sized by the tile count.
constexpr uint32_t kBindingTileRanges = 3;     // uint[2 per tile]: lowest, highest density key
constexpr uint32_t kBindingTileDirty = 4;      // uint per tile: range stale (written since computed)
constexpr uint32_t kBindingActiveTiles = 5;    // uint per tile: ids of the current phase's active tiles
constexpr uint32_t kBindingActiveDispatch = 6; // uint[8]: two VkDispatchIndirectCommand records (+ active tile count)
constexpr uint32_t kBindingSkipStats = 7;      // uint: the (tile, phase) pairs a run dispatched
// uint words, a bit per voxel of every tile (tiles of at most 16 voxels per axis; else one word):
// where the package's occupancy level holds (codegen::OccupancyLevel, tiles.glsl occupancyBit).
constexpr uint32_t kBindingTileOccupancy = 13;
// uint per voxel, same chunk-major addresses as kBindingVoxels: the voxel's material id (0..255).
// Allocated at grid size only when KernelPackage::usesMaterials; otherwise a one-element buffer
// that no kernel declares.
constexpr uint32_t kBindingMaterials = 8;
// uint[3]: the current stage's non-finite replacements (count low, count high, lowest grid index;
// compiler/shaders/nonfinite.glsl), declared by the kernels that may compute a non-finite density
// (field and sweep kernels). The runtime copies it out after each stage and resets it to {0, 0, ~0u}.
constexpr uint32_t kBindingNonFinite = 9;
// int words: KernelPackage::pointSets with their per-cell lists (voxc::pointSetWords, layout in
// compiler/shaders/lsystem_carve.glsl), declared only by field kernels that read a point set;
// otherwise a one-element buffer.
constexpr uint32_t kBindingPointSets = 10;
// int words: KernelPackage::solveTables (voxc::solveTableWords, layout in
// compiler/shaders/solve_tables.glsl), declared only by curves kernels; otherwise a one-element buffer.
constexpr uint32_t kBindingSolveTables = 12;
// uint words a stage's passes hand to each other (StagePlan::scratchWords, the largest over the
// stages; one word when none needs any): a speleothem stage's air mask (speleothems.glsl), the
// rule each anchor of a sweep with stamps fired and its phase's firing bits (StampKernel.cpp).
constexpr uint32_t kBindingScratch = 11;

constexpr uint32_t kNoKernel = UINT32_MAX;

struct Kernel {
    std::string name;               // e.g. "start", "overhang_sweep0"; also the file stem in a package
    std::string origin;             // which .vox construct it came from, e.g. "overhang.vox:14:3 grammar overhang, window [3,3,1]"
    std::string glsl;               // generated source
    std::vector<uint32_t> spirv;    // compiled, validated SPIR-V
    // The descriptor set 0 bindings the SPIR-V declares, ascending (read back from it, so the
    // manifest lists exactly what a pipeline layout must provide).
    std::vector<uint32_t> bindings;
    uint32_t localSize[3] = {8, 8, 1};
    // Each invocation handles a block of this many consecutive anchors of its dispatch per axis
    // (the kernel's ANCHORS_PER_INVOCATION); a workgroup covers localSize * anchorsPerInvocation.
    uint32_t anchorsPerInvocation[3] = {1, 1, 1};
};

struct SweepPlan {
    uint32_t kernel = 0;       // index into KernelPackage::kernels
    // Run before each phase when tiles are skipped: lists the tiles where a rule may match and
    // writes the sweep kernel's indirect dispatch. kNoKernel: the sweep has no live rule.
    uint32_t activeTilesKernel = kNoKernel;
    glm::ivec3 window{1};
    glm::ivec3 phaseCount{1};  // as Sweep::phaseCount
    // Run after each phase when the sweep's rules stamp fields (stamp.glsl): one invocation per
    // voxel of the phase's windows grown by stampReach, clipped to the grid; its push block's
    // anchorStep.xyz is the phase's first anchor. Such a sweep runs over every anchor (no tile
    // skipping: the sweep kernel records each anchor's rule in kBindingScratch), and the tile
    // ranges are stale after it. kNoKernel: no stamps.
    uint32_t stampKernel = kNoKernel;
    glm::ivec3 stampReach{0};
    // Per phase p (x fastest): anchors start + i*step, i < count, as voxc::phaseAnchors computes.
    std::vector<glm::ivec3> phaseStart, phaseStep, phaseCount3;
};

// Fills plan.phaseStart/phaseStep/phaseCount3 from voxc::phaseAnchors, one entry per phase of
// `sweep` in execution order, so every plan builder expands phases the one way.
inline void fillPhaseAnchors(SweepPlan& plan, const Grammar& grammar, const Sweep& sweep) {
    for (int p = 0; p < sweep.phases(); ++p) {
        const PhaseAnchors anchors = phaseAnchors(grammar, sweep, p);
        plan.phaseStart.push_back(anchors.start);
        plan.phaseStep.push_back(anchors.step);
        plan.phaseCount3.push_back(anchors.count);
    }
}

struct GrammarPlan {
    std::string name;
    uint32_t iterations = 1;
    std::vector<SweepPlan> sweeps; // in execution order; index = sweep index for hashing
};

// A box of grid voxels a field stage dispatches on its own: min <= local < max. Constant: interval
// analysis (ir::classifyFieldChunks) proved the field exactly `value` there, so the kernel only
// combines with it. Unchanged: a constant box whose combine provably leaves every density as it
// is (e.g. union with 0 where every density is >= 0); it is not dispatched at all.
struct FieldBox {
    glm::ivec3 min{0}, max{0};
    bool constant = false;
    float value = 0.0f;
    bool unchanged = false;
};

// How the runtime runs one pipeline stage, whatever its kind: a grid pass (one kernel over the
// grid or over boxes of it), a repeated program of sweeps, or both (the grid pass first).
struct StagePlan {
    std::string kind;  // the stage kind's name (voxc/stages/StageKind.h): "start", "grammar", "field"
    SourceLoc loc;     // the pipeline entry (Stage::loc), for reports naming the stage
    std::string label; // Stage::label
    // Members the manifest lists for this kind after "kind", e.g. ("field", "ground"), ("mode", "set").
    std::vector<std::pair<std::string, std::string>> attributes;
    // The grid pass: one dispatch per box of gridBoxes (disjoint, covering the grid), or over the
    // whole grid when it is empty; it rewrites densities, so tile ranges go stale afterwards
    // unless writesDensities is false (a paint stage writes materials only).
    uint32_t gridKernel = kNoKernel;
    // Run over the whole grid before the grid pass, behind a barrier: a pass that prepares what
    // the grid pass reads from kBindingScratch (a speleothem stage's air mask). kNoKernel: none.
    uint32_t prepassKernel = kNoKernel;
    uint64_t scratchWords = 0; // kBindingScratch words the stage's passes use
    std::vector<FieldBox> gridBoxes;
    bool writesDensities = true;
    // The grid pass writes every grid voxel's density and reads none first (a start stage; a `set`
    // field stage with no unchanged box), so as the first stage it makes clearing the grid needless.
    bool writesEveryDensity = false;
    std::optional<uint8_t> material; // Stage::material, when the stage writes one
    std::optional<GrammarPlan> grammar; // the sweeps, repeated grammar->iterations times
    // How far a voxel after the stage depends on voxels before it, per axis (stages::StageRadius).
    glm::ivec3 dependencyRadius{0};
};

// The dispatch shape of a global solve (docs/architecture.md, "Stage kinds"), kind-free: kernels
// over a few dense storage buffers (binding b = buffers[b]; domain-major, so the result does not
// depend on chunks), run as `prologue` once, then `cycle` repeated while the convergence measure
// is above `tolerance`, at most `maxCycles` times. Levels, ping-pong halves and colours are data of
// the steps (their push words), so a multigrid V-cycle (smoothing, restriction, prolongation
// between levels) and a fixed-sweep Jacobi schedule are both a list of steps. Each step waits for
// the one before it. The measure (after the prologue and after every cycle), by `stop`:
// MeasureAtMost: buffers[measureBuffer] word 0 cleared to 0, then `measure` run, then that word read
// back as a float, the cycles stopping once it is <= tolerance; CountIsZero: `measure` run, then
// that word read back as a count, the cycles stopping once it is 0 (a BFS front that ran out: each
// cycle expands a few layers, a layer's dispatch sized on the device by an indirect step).
// A fixed schedule (so many sweeps) is a prologue alone, maxCycles 0.
struct SolveStep {
    uint32_t kernel = 0;                // index into SolveProgram::kernels
    uint32_t groups[3] = {1, 1, 1};     // workgroups per axis, unless indirect
    std::array<int32_t, 16> push{};     // the kernel's push-constant block (64 bytes)
    // Indirect: the workgroup counts are the three words at indirectWord of buffers[indirectBuffer],
    // as an earlier step wrote them.
    bool indirect = false;
    uint32_t indirectBuffer = 0, indirectWord = 0;
};

struct SolveProgram {
    enum class Stop { MeasureAtMost, CountIsZero };
    std::vector<Kernel> kernels;        // SPIR-V; push constants are SolveStep::push
    std::vector<uint64_t> bufferWords;  // 32-bit words of each storage buffer, binding = index
    std::vector<SolveStep> prologue, cycle, measure;
    Stop stop = Stop::MeasureAtMost;
    uint32_t measureBuffer = 0;
    uint32_t measureWord = 0;           // CountIsZero: the count's word in buffers[measureBuffer]
    float tolerance = 0.0f;
    int32_t maxCycles = 0;
};

struct KernelPackage {
    World world;
    bool usesMaterials = false; // Program::usesMaterials(): kernels read/write kBindingMaterials
    std::vector<Material> materials; // Program::materials, for the manifest's material table
    std::vector<Kernel> kernels;
    std::vector<StagePlan> stages;
    // The stages' dependency radii summed, capped at world size - 1: the halo a region of the
    // world is computed with (voxc/stages/Region.h).
    glm::ivec3 halo{0};
    // Recomputes the density range of every stale tile, before each sweep when tiles are
    // skipped. kNoKernel: the package cannot skip tiles (every sweep runs over every anchor).
    uint32_t tileRangesKernel = kNoKernel;
    // The point sets field kernels read, `pointSetDistances(i, p)` naming entry i
    // (codegen::pointSetsOf); the runtime uploads them with their lists into kBindingPointSets.
    std::vector<std::shared_ptr<const PointSet>> pointSets;
    // The solve tables curves kernels read (their SOLVE_TABLE constant indexes this list); the
    // runtime uploads them into kBindingSolveTables.
    std::vector<std::shared_ptr<const SolveTable>> solveTables;
};

} // namespace voxc

#pragma once
// Generated GLSL for each kind of kernel, built from the templates in compiler/shaders; the
// stage kinds' records (compiler/stages) put them together into a package.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/ir/Ir.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::codegen {

// The occupancy level of a package: tiles keep a bit per voxel of `density >= value` (`>` when
// strict), chosen as the level that decides the most rule cells (a cell decided by it passes only
// on one side), so an active-tiles kernel can look for a rule's pattern of such cells
// (ActiveTilesKernel.cpp). The sweep kernels keep the bits of the voxels they write.
struct OccupancyLevel {
    float value = 0;
    bool strict = false;
};

// How a kernel's invocations cover the anchors of a dispatch: Kernel::localSize and
// Kernel::anchorsPerInvocation, which the generated source repeats as its layout and
// ANCHORS_PER_INVOCATION.
struct DispatchShape {
    uint32_t localSize[3];
    uint32_t anchorsPerInvocation[3];
};

// A kernel of the package: `glsl` compiled to validated SPIR-V (with VOXC_MATERIALS defined when
// the package stores materials), its bindings read back from the SPIR-V.
Kernel makeKernel(std::string name, std::string origin, const DispatchShape& shape, std::string glsl,
                  bool usesMaterials);

// The DISPATCH_SHAPE section of a template: the local size layout and ANCHORS_PER_INVOCATION.
std::string dispatchShapeGlsl(const DispatchShape& shape);

// `sourceName` is how comments name the .vox file (its file name, so output does not
// depend on the directory it was compiled from).
DispatchShape startDispatchShape(const ir::IrModule& module);
std::string startKernelSource(const ir::IrModule& module, std::string_view sourceName);

// A field stage's kernel "<field>_<mode>": column-walking like the start kernel (same shape).
// `stages` are the pipeline stages that run it (for the header comment).
// Bounds of every grid density before a stage, when known.
struct DensityBounds {
    float lo = 0.0f, hi = 0.0f;
};

// The boxes a field stage dispatches: its chunks classified by interval analysis, runs of
// neighbours with the same class (and constant) merged into boxes, along x, then y, then z; with `before`
// known, constant boxes whose combine cannot change a density in it are marked unchanged.
// A paint box with a constant is unchanged without `before` when the constant or the stage's
// material leaves every voxel's material alone.
// `after` bounds every density once the stage ran (from the field's bounds over all chunks),
// when `before` is known or the stage is a `set`, and the field's bounds are finite.
struct FieldStageBoxes {
    std::vector<FieldBox> boxes;
    std::optional<DensityBounds> after;
};
FieldStageBoxes fieldBoxes(const ir::IrModule& module, const ir::IrField& field, FieldMode mode,
                           std::optional<uint8_t> material, std::optional<DensityBounds> before);
// Voxels one invocation of a field kernel walks along its column: the whole column, or at most
// kPointSetAnchorsAlongY where the field reads a point set per voxel (lsystem_carve.glsl: up to
// 2,050 list loop iterations per voxel in blocks of 8 items, under lavapipe's 65,535 per
// invocation group for every loop together); at most 32 where every lookup is shared along the
// column (FieldKernel.cpp's kPointSetColumnAnchorsAlongY, point_set_column.glsl).
constexpr uint32_t kPointSetAnchorsAlongY = 8;
// The list items a field kernel's lookup visits per loop iteration (lsystem_carve.glsl's
// POINT_SET_BLOCK): 1 where the field's lists are short enough that its voxels loop no more often
// than one point set's could in blocks of 8 at kMaxPointSetPerCell, else 8. Every step of a block
// costs all its loads, live or not, and most lookups end after a step or two.
uint32_t fieldPointSetListBlock(const ir::IrField& field);
DispatchShape fieldDispatchShape(const ir::IrModule& module, const ir::IrField& field);
// `material`: the stages' material (Stage::material), written as voxc::combineField does.
std::string fieldKernelSource(const ir::IrModule& module, const ir::IrField& field, FieldMode mode,
                              std::optional<uint8_t> material, const std::vector<Stage>& stages, std::string_view kernelName,
                              std::string_view sourceName);

// A speleothem stage (voxc::caves, speleothems.glsl): the air-mask prepass every such stage shares,
// then the stage's grow kernel, both column-walking (the start kernel's shape). `clearanceSet`:
// the index in KernelPackage::pointSets of the keep_clear carve, whose clearance is never written.
DispatchShape speleothemDispatchShape(const ir::IrModule& module);
std::string speleothemMaskKernelSource(const ir::IrModule& module, std::string_view sourceName);
std::string speleothemGrowKernelSource(const ir::IrModule& module, const SpeleothemStage& stage,
                                       std::optional<uint8_t> material, std::optional<uint32_t> clearanceSet,
                                       std::string_view kernelName, std::string_view sourceName);

DispatchShape sweepDispatchShape(const ir::IrSweep& sweep);
std::string sweepKernelSource(const ir::IrGrammar& grammar, const ir::IrSweep& sweep, std::string_view kernelName,
                              std::string_view sourceName, const std::optional<OccupancyLevel>& level);

// A field evaluated in a stamp's frame (x, y, z = `stampPosition`, a vec3; wx, wy, wz from
// `world`, an ivec3): straight-line statements, the root's name and the libraries they call.
struct StampFieldCode {
    std::string statements;
    std::string value;
    std::vector<std::string_view> libraries;
};
StampFieldCode stampFieldGlsl(const ir::IrModule& module, const ir::IrField& field, std::string_view sourceName);
// voxc::combineField of the density at `address` with the float expression `f` (a field stage's combine).
std::string combineFieldGlsl(FieldMode mode, std::optional<uint8_t> material, const std::string& f);

// The stamp pass of a sweep with stamps (stamp.glsl): after each phase, one invocation per voxel
// the phase's grown windows cover folds their stamps in anchor order. Sweeps with stamps record
// the rule each anchor fired in kBindingScratch (sweepFiredWords words).
DispatchShape stampDispatchShape();
std::string stampKernelSource(const ir::IrModule& module, const ir::IrGrammar& grammar, const ir::IrSweep& sweep,
                              std::string_view kernelName, std::string_view sourceName);
bool sweepHasStamps(const ir::IrSweep& sweep);
// The FiredRule buffer (kBindingScratch): the rule each anchor fired (firedIndex(anchor)) and the
// phase's firing bits (firingRow), shared by the sweep and stamp kernels.
std::string firedRecordGlsl(const ir::IrGrammar& grammar, const ir::IrSweep& sweep);
// The sweep kernel's write of its anchor's firing bit, after `chosen` is known.
std::string firingBitGlsl(const ir::IrSweep& sweep);
uint64_t sweepFiredWords(const ir::IrSweep& sweep);
// The largest reach of the sweep's stamps per axis: how far the stamp pass reaches past the windows.
glm::ivec3 sweepStampReach(const ir::IrSweep& sweep);

// Tile skipping: the per-sweep kernel that lists the tiles where a live rule may match
// (active_tiles.glsl), and the kernel that recomputes stale tile ranges and occupancy bits
// (tile_ranges.glsl), each with the package's occupancy level.
std::optional<OccupancyLevel> occupancyLevel(const ir::IrModule& module); // none: no cell is decided
// The OCCUPANCY_LEVEL section of tiles.glsl.
std::string occupancyLevelGlsl(const std::optional<OccupancyLevel>& level);
DispatchShape activeTilesDispatchShape();
std::string activeTilesKernelSource(const ir::IrGrammar& grammar, const ir::IrSweep& sweep,
                                     std::string_view kernelName, std::string_view sourceName,
                                     const std::optional<OccupancyLevel>& level);
DispatchShape tileRangesDispatchShape();
std::string tileRangesKernelSource(const std::optional<OccupancyLevel>& level);

} // namespace voxc::codegen

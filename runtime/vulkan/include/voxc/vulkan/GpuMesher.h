#pragma once
// Marching cubes on the Vulkan device, over the voxel and material buffers a VulkanExecutor's
// run() left there (no densities cross to the host). Passes, each behind a pipeline barrier on
// the one before (a workgroup barrier orders nothing between workgroups): a tiles pass records
// on which sides of iso the voxels of each world-aligned 8^3 tile lie (reading only the tiles
// that the tile ranges of the executor's read-back, where it read back, leave open), from which the host lists
// the tiles of cells the surface crosses (the active tiles) and their rows of cells in global
// order; then a count pass over those rows alone (per cell its case), from whose cases the host
// lists the active cells with their first vertex and triangle and the vertices with their owner
// cell, in global order; and emit passes over those lists that write every vertex and triangle
// at its place (docs/architecture.md, "On the device"). The mesh
// is the CPU mesher's (voxc/mesh/MarchingCubes.h, the oracle): the same case table, vertices
// ordered by global edge, triangles by global cell then table order, the same arithmetic; so the
// index buffer and the materials are identical, and positions and normals bit-identical where
// the device rounds as IEEE 754 requires (lavapipe; tests/mesh/GpuMesherTest; no other device
// has been tried). MeshStats' chunks, skipped chunks, tiles and active tiles are the CPU
// mesher's.
#include "voxc/mesh/SurfaceNets.h"
#include "voxc/vulkan/Executor.h"

#include <memory>

namespace voxc {

class GpuMarchingCubes {
public:
    // Builds the passes' pipelines and the buffers sized by the executor's grid. UserError when
    // the device lacks shaderFloat64 (the crossings are computed in double, as on the CPU) or
    // the grid's cells need buffers larger than the device can bind. `executor` must outlive this.
    explicit GpuMarchingCubes(VulkanExecutor& executor);
    ~GpuMarchingCubes();
    GpuMarchingCubes(const GpuMarchingCubes&) = delete;
    GpuMarchingCubes& operator=(const GpuMarchingCubes&) = delete;

    // Meshes the grid of the executor's last run() (InternalError before any run). UserError when
    // the mesh needs more memory than the device can bind as one buffer.
    Mesh mesh(const MeshOptions& options, MeshStats* stats = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc

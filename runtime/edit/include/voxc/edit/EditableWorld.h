#pragma once
// A generated grid with its marching-cubes mesh, edited by brushes (voxc/edit/Brush.h) and picked
// by rays (voxc/edit/Pick.h): the C++ API of deformation, without a viewer.
//
// The mesh is made whole (meshMarchingCubes: uniform tiles skipped on the grid's tile ranges, both
// cores), at construction and again when mesh() is asked after edits: faster than keeping every
// chunk's share and welding them (at 256x128x256, making the shares takes seconds and each weld
// longer than meshing the whole grid), and byte for byte the same mesh. An edit keeps the grid's tile ranges
// up to date over the voxels it changed, so the next mesh skips the uniform tiles again.
//
// An edit diffs the densities it writes; V is the box of voxels whose bits changed. The chunks
// whose share of the mesh it can change are exactly those owning a cell in [Vmin - 2, Vmax + 1]
// (meshing spec §2.5 R2): a cell reads its 8 corners, and its vertices' normals (central
// differences) one sample beyond them; EditResult names them, for a caller that keeps meshes per
// chunk. The mesh after any sequence of edits is, byte for byte, the chunk-by-chunk mesher's
// (LodMesher at level 0) of the current grid (the meshers are deterministic per global grid edge).
// A no-op edit (carve in air, add in rock) changes no voxel and leaves the mesh as it is. Named
// EditableWorld because voxc::World is the program's world settings.
#include "voxc/edit/Brush.h"
#include "voxc/edit/Pick.h"
#include "voxc/mesh/SurfaceNets.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace voxc {

struct Mesh;

struct EditResult {
    std::optional<VoxelBox> changed;       // grid-local voxels whose density changed
    // The chunks whose share of the mesh the edit can change (R2), world chunk coordinates.
    std::vector<glm::ivec3> chunksRemeshed;
};

class EditableWorld {
public:
    EditableWorld(ChunkedGrid grid, const MeshOptions& options = {});
    ~EditableWorld();
    EditableWorld(EditableWorld&&) noexcept;
    EditableWorld& operator=(EditableWorld&&) noexcept;

    const ChunkedGrid& grid() const;
    EditResult edit(const Brush& brush);
    std::optional<PickHit> pick(glm::vec3 origin, glm::vec3 direction, float maxDistance = 1e30f) const;
    // The mesh of the grid as it now stands, made again when asked after an edit (valid until the next edit).
    const Mesh& mesh() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace voxc

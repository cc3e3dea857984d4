#pragma once
// A generated grid with its marching-cubes mesh kept per chunk, edited by brushes (voxc/edit/Brush.h)
// and picked by rays (voxc/edit/Pick.h): the C++ API of deformation, without a viewer.
//
// Built, the world is meshed whole (meshMarchingCubes: uniform tiles skipped on the grid's tile
// ranges, both cores), several times faster than chunk by chunk and byte for byte the same mesh;
// the chunks' shares (LodMesher) are made on the first edit that changes a voxel, so a world that
// is only looked at never pays for them. mesh() is kept: welded from the shares when asked after
// edits, once.
//
// An edit diffs the densities it writes; V is the box of voxels whose bits changed. The chunks
// re-meshed are exactly those owning a cell in [Vmin - 2, Vmax + 1] (meshing spec §2.5 R2): a cell
// reads its 8 corners, and its vertices' normals (central differences) one sample beyond them.
// That is LodMesher::update over V with a layout of only level 0, so the mesh after any sequence of
// edits is, byte for byte, meshMarchingCubes of the current grid (the meshers are deterministic per
// global grid edge). A no-op edit (carve in air, add in rock) changes no voxel and re-meshes
// nothing. Named EditableWorld because voxc::World is the program's world settings.
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
    std::vector<glm::ivec3> chunksRemeshed; // world chunk coordinates
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
    // The welded mesh of every chunk as it now stands (valid until the next edit).
    const Mesh& mesh() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace voxc

#include "voxc/edit/EditableWorld.h"

#include "voxc/mesh/Lod.h"
#include "voxc/mesh/MarchingCubes.h"

namespace voxc {

// The mesher refers to the pyramid, which refers to the grid: all three live here, in place.
struct EditableWorld::State {
    State(ChunkedGrid g, const MeshOptions& options)
        : grid(std::move(g)), options(options), mesh(meshMarchingCubes(grid, options)) {}
    ChunkedGrid grid;
    MeshOptions options;
    Mesh mesh;
    bool meshStale = false; // edits since `mesh`: mesh() welds the chunks' shares again
    std::optional<LodPyramid> pyramid; // with the mesher, from the first edit that changes a voxel
    std::optional<LodMesher> mesher;
};

EditableWorld::EditableWorld(ChunkedGrid grid, const MeshOptions& options)
    : state_(std::make_unique<State>(std::move(grid), options)) {}
EditableWorld::~EditableWorld() = default;
EditableWorld::EditableWorld(EditableWorld&&) noexcept = default;
EditableWorld& EditableWorld::operator=(EditableWorld&&) noexcept = default;

const ChunkedGrid& EditableWorld::grid() const { return state_->grid; }

EditResult EditableWorld::edit(const Brush& brush) {
    EditResult result;
    result.changed = applyBrush(state_->grid, brush);
    if (!result.changed) return result;
    State& s = *state_;
    if (!s.mesher) {
        // Every chunk meshed from the edited grid; the update below re-meshes the edit's chunks
        // again (a few), only to name them as every later edit does. A pyramid of level 0 alone
        // has no level to refresh.
        s.pyramid.emplace(s.grid, 0);
        s.mesher.emplace(*s.pyramid, LodLayout::uniform(s.grid.layout(), 0), s.options);
    }
    result.chunksRemeshed = s.mesher->update(result.changed->first, result.changed->last);
    s.meshStale = true;
    return result;
}

std::optional<PickHit> EditableWorld::pick(glm::vec3 origin, glm::vec3 direction, float maxDistance) const {
    return voxc::pick(state_->grid, state_->options.iso, origin, direction, maxDistance);
}

const Mesh& EditableWorld::mesh() const {
    State& s = *state_;
    if (s.meshStale) s.mesh = s.mesher->mesh(), s.meshStale = false;
    return s.mesh;
}

} // namespace voxc

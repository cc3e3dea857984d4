#include "voxc/edit/EditableWorld.h"

#include "voxc/mesh/Lod.h"

namespace voxc {

// The mesher refers to the pyramid, which refers to the grid: all three live here, in place.
struct EditableWorld::State {
    State(ChunkedGrid g, const MeshOptions& options)
        : grid(std::move(g)), iso(options.iso), pyramid(grid, 0),
          mesher(pyramid, LodLayout::uniform(grid.layout(), 0), options) {}
    ChunkedGrid grid;
    float iso;
    LodPyramid pyramid;
    LodMesher mesher;
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
    result.chunksRemeshed = state_->mesher.update(result.changed->first, result.changed->last);
    return result;
}

std::optional<PickHit> EditableWorld::pick(glm::vec3 origin, glm::vec3 direction, float maxDistance) const {
    return voxc::pick(state_->grid, state_->iso, origin, direction, maxDistance);
}

Mesh EditableWorld::mesh() const { return state_->mesher.mesh(); }

} // namespace voxc

#include "voxc/edit/EditableWorld.h"

#include "voxc/mesh/MarchingCubes.h"

#include <glm/common.hpp>

namespace voxc {

struct EditableWorld::State {
    State(ChunkedGrid g, const MeshOptions& options)
        : grid(std::move(g)), options(options), mesh(meshMarchingCubes(grid, options)) {}
    ChunkedGrid grid;
    MeshOptions options;
    Mesh mesh;
    bool meshStale = false; // edits since `mesh`: mesh() meshes the grid again
};

EditableWorld::EditableWorld(ChunkedGrid grid, const MeshOptions& options)
    : state_(std::make_unique<State>(std::move(grid), options)) {}
EditableWorld::~EditableWorld() = default;
EditableWorld::EditableWorld(EditableWorld&&) noexcept = default;
EditableWorld& EditableWorld::operator=(EditableWorld&&) noexcept = default;

const ChunkedGrid& EditableWorld::grid() const { return state_->grid; }

EditResult EditableWorld::edit(const Brush& brush) {
    State& s = *state_;
    EditResult result;
    result.changed = applyBrush(s.grid, brush); // keeps the tile ranges the next mesh() skips on
    if (!result.changed) return result;
    const glm::ivec3 first = result.changed->first, last = result.changed->last;
    // R2: the cells whose output can change, [first - 2, last + 1], within the grid's cells
    // [-1, size - 1]; the chunks owning them, as cellChunks names chunks.
    const ChunkLayout& layout = s.grid.layout();
    const glm::ivec3 cellFirst = glm::max(first - 2, glm::ivec3(-1)), cellLast = glm::min(last + 1, layout.gridSize - 1);
    const glm::ivec3 chunkFirst = (layout.gridOrigin + cellFirst) >> layout.chunkShift;
    const glm::ivec3 chunkLast = (layout.gridOrigin + cellLast) >> layout.chunkShift;
    for (int z = chunkFirst.z; z <= chunkLast.z; ++z)
        for (int y = chunkFirst.y; y <= chunkLast.y; ++y)
            for (int x = chunkFirst.x; x <= chunkLast.x; ++x) result.chunksRemeshed.push_back({x, y, z});
    s.meshStale = true;
    return result;
}

std::optional<PickHit> EditableWorld::pick(glm::vec3 origin, glm::vec3 direction, float maxDistance) const {
    return voxc::pick(state_->grid, state_->options.iso, origin, direction, maxDistance);
}

const Mesh& EditableWorld::mesh() const {
    State& s = *state_;
    if (s.meshStale) s.mesh = meshMarchingCubes(s.grid, s.options), s.meshStale = false;
    return s.mesh;
}

} // namespace voxc

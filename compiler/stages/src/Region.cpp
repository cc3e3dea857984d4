#include "voxc/stages/Region.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <charconv>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <memory>

namespace voxc::stages {

namespace {

int32_t ceilDiv(int32_t a, int32_t b) { return a >= 0 ? (a + b - 1) / b : -(-a / b); }

// The grammar's anchors inside `box`: the declared lattice (boundsMin + n * stride) from its first
// point at or past the box's min, numbered on from there, the bounds clipped to the box.
Grammar regionGrammar(Grammar grammar, const GridBox& box) {
    const glm::ivec3 size = box.size();
    for (int axis = 0; axis < 3; ++axis) {
        const int32_t lattice = grammar.boundsMin[axis] - box.min[axis]; // declared first anchor, here
        const int32_t skipped = lattice >= 0 ? 0 : ceilDiv(-lattice, grammar.stride[axis]);
        const int32_t lo = std::min(lattice + skipped * grammar.stride[axis], size[axis]);
        const int32_t hi = std::clamp(grammar.boundsMax[axis] - box.min[axis], lo, size[axis]);
        grammar.boundsMin[axis] = lo;
        grammar.boundsMax[axis] = hi;
        grammar.firstAnchor[axis] += skipped;
    }
    return grammar;
}

} // namespace

std::shared_ptr<const SolveTable> regionTable(const SolveTable& table, const GridBox& box) {
    auto out = std::make_shared<SolveTable>();
    // A table the box does not meet becomes an empty one inside the box (its plan then skips the
    // whole grid), not one placed past the grid's end.
    const glm::ivec3 lo = glm::clamp(table.min, box.min, box.max);
    const glm::ivec3 hi = glm::max(glm::min(table.min + table.size, box.max), lo);
    out->min = lo - box.min;
    out->size = hi - lo;
    out->source = table.source;
    out->notes = table.notes;
    out->solves = table.solves;
    out->terrainMaps = table.terrainMaps;
    const bool materials = !table.material.empty();
    for (int32_t z = lo.z; z < hi.z; ++z)
        for (int32_t y = lo.y; y < hi.y; ++y)
            for (int32_t x = lo.x; x < hi.x; ++x) {
                const glm::ivec3 c = glm::ivec3(x, y, z) - table.min;
                const size_t at = size_t(c.x) + size_t(table.size.x) * (size_t(c.y) + size_t(table.size.y) * size_t(c.z));
                out->density.push_back(table.density[at]);
                if (materials) out->material.push_back(table.material[at]);
            }
    return out;
}

namespace {

int32_t parseInt(std::string_view text, const std::string& whole) {
    int32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw UserError(fmt::format("--region {}: '{}' is not an integer", whole, text));
    return value;
}

glm::ivec3 parseCorner(std::string_view text, const std::string& whole) {
    glm::ivec3 corner;
    for (int axis = 0; axis < 3; ++axis) {
        const size_t comma = axis < 2 ? text.find(',') : text.size();
        if (comma == std::string_view::npos || (axis == 2 && text.find(',') != std::string_view::npos))
            throw UserError(fmt::format("--region {}: a corner is three integers X,Y,Z", whole));
        corner[axis] = parseInt(text.substr(0, comma), whole);
        text = axis < 2 ? text.substr(comma + 1) : std::string_view();
    }
    return corner;
}

} // namespace

PipelineHalo pipelineHalo(const Program& program) {
    PipelineHalo halo;
    const glm::ivec3 cap = program.world.size - 1;
    for (const Stage& stage : program.pipeline) {
        halo.stages.push_back(stageKind(stage.kind).dependencyRadius(program, stage));
        halo.radius = glm::min(halo.radius + halo.stages.back().radius, cap);
    }
    return halo;
}

GridBox haloBox(const Program& program, const GridBox& region, glm::ivec3 halo) {
    return {glm::max(region.min - halo, glm::ivec3(0)), glm::min(region.max + halo, program.world.size)};
}

Program regionProgram(const Program& program, const GridBox& box) {
    VOXC_ASSERT(program.world.localBase == glm::ivec3(0));
    VOXC_ASSERT(glm::all(glm::lessThanEqual(glm::ivec3(0), box.min)) && glm::all(glm::lessThan(box.min, box.max)) &&
                glm::all(glm::lessThanEqual(box.max, program.world.size)));
    Program region = program;
    region.world.size = box.size();
    region.world.origin = program.world.origin + box.min;
    region.world.localBase = box.min;
    for (Grammar& grammar : region.grammars) grammar = regionGrammar(grammar, box);
    for (CurvesBlock& block : region.curves) {
        const glm::ivec3 lo = glm::max(block.min, box.min);
        const glm::ivec3 hi = glm::max(glm::min(block.min + block.size, box.max), lo);
        block.min = lo - box.min;
        block.size = hi - lo;
        // A curves block not solved yet is solved whole and cropped by stages::solveBlocks.
        if (block.table) block.table = regionTable(*block.table, box);
    }
    return region;
}

DenseGrid cropGrid(const DenseGrid& grid, const GridBox& box) {
    DenseGrid out(box.size());
    for (int32_t z = 0; z < box.size().z; ++z)
        for (int32_t y = 0; y < box.size().y; ++y)
            for (int32_t x = 0; x < box.size().x; ++x) {
                out.at({x, y, z}) = grid.at(box.min + glm::ivec3(x, y, z));
                out.materialAt({x, y, z}) = grid.materialAt(box.min + glm::ivec3(x, y, z));
            }
    return out;
}

std::pair<glm::ivec3, glm::ivec3> parseWorldBox(const std::string& text) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos)
        throw UserError(fmt::format("--region {}: expected MINX,MINY,MINZ:MAXX,MAXY,MAXZ (world voxels, max excluded)", text));
    const glm::ivec3 lo = parseCorner(std::string_view(text).substr(0, colon), text);
    const glm::ivec3 hi = parseCorner(std::string_view(text).substr(colon + 1), text);
    if (!glm::all(glm::lessThan(lo, hi)))
        throw UserError(fmt::format("--region {}: the box is empty; each min must be below its max", text));
    return {lo, hi};
}

GridBox parseRegion(const std::string& text, const World& world) {
    const auto [lo, hi] = parseWorldBox(text);
    const glm::ivec3 worldMax = world.origin + world.size;
    if (!glm::all(glm::lessThanEqual(world.origin, lo)) || !glm::all(glm::lessThanEqual(hi, worldMax)))
        throw UserError(fmt::format("--region {}: the box must lie inside the world, {},{},{}:{},{},{}", text,
                                    world.origin.x, world.origin.y, world.origin.z, worldMax.x, worldMax.y,
                                    worldMax.z));
    return {lo - world.origin, hi - world.origin};
}

} // namespace voxc::stages

// Transition cells derived per case from the facet rule (voxc/mesh/TransitionCells.h).
#include "voxc/mesh/TransitionCells.h"

#include "LoopTriangulation.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

namespace voxc::transition_cells {
namespace {

// A sub-edge as a small integer, for the per-case tables below.
constexpr int kSubEdgeIds = kPoints * 6;
int subEdgeId(const SubEdge& e) { return e.lower * 6 + e.axis * 2 + (e.halfSteps - 1); }
SubEdge subEdgeOf(int id) { return {uint8_t(id / 6), uint8_t((id % 6) / 2), uint8_t(id % 2 + 1)}; }

SubEdge subEdgeBetween(int a, int b) {
    const glm::ivec3 d = pointOffset(b) - pointOffset(a);
    for (int axis = 0; axis < 3; ++axis)
        if (d[axis] != 0) {
            const int lower = d[axis] > 0 ? a : b;
            return {uint8_t(lower), uint8_t(axis), uint8_t(std::abs(d[axis]))};
        }
    throw InternalError("transition cells: a facet repeats a point");
}

glm::vec3 midpoint(const SubEdge& e) {
    glm::vec3 p(pointOffset(e.lower));
    p[e.axis] += 0.5f * float(e.halfSteps);
    return p;
}

bool present(uint32_t points, glm::ivec3 p) { return (points >> pointAt(p)) & 1u; }

// The facets of the cell's surface, each a ring of points counter-clockwise seen from outside.
std::vector<std::vector<int>> facets(uint32_t points) {
    std::vector<std::vector<int>> result;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            auto point = [&](int cu, int cv) {
                glm::ivec3 p;
                p[axis] = 2 * side;
                p[u] = cu;
                p[v] = cv;
                return p;
            };
            // Counter-clockwise in (u, v), which is seen from +axis; the low side is reversed.
            std::vector<std::vector<glm::ivec2>> rings;
            if (present(points, point(1, 1))) {
                rings = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}},
                         {{1, 1}, {2, 1}, {2, 2}, {1, 2}}, {{0, 1}, {1, 1}, {1, 2}, {0, 2}}};
            } else {
                std::vector<glm::ivec2> ring;
                for (glm::ivec2 q : {glm::ivec2{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}})
                    if ((q.x != 1 && q.y != 1) || present(points, point(q.x, q.y))) ring.push_back(q);
                rings = {ring};
            }
            for (std::vector<glm::ivec2>& ring : rings) {
                if (side == 0) std::reverse(ring.begin(), ring.end());
                std::vector<int> facet;
                for (glm::ivec2 q : ring) facet.push_back(pointAt(point(q.x, q.y)));
                result.push_back(facet);
            }
        }
    return result;
}

} // namespace

bool validShape(uint32_t points) {
    if ((points & kCornerPoints) != kCornerPoints || points >= (1u << kPoints)) return false;
    for (int point = 0; point < kPoints; ++point) {
        if (!((points >> point) & 1u)) continue;
        const glm::ivec3 p = pointOffset(point);
        const int halves = (p.x == 1) + (p.y == 1) + (p.z == 1);
        if (halves == 3) return false;
        if (halves == 2)
            for (int axis = 0; axis < 3; ++axis) {
                if (p[axis] != 1) continue;
                for (int end : {0, 2}) {
                    glm::ivec3 edgeMid = p;
                    edgeMid[axis] = end;
                    if (!present(points, edgeMid)) return false;
                }
            }
    }
    return true;
}

CellTriangles deriveCell(uint32_t points, uint32_t solid) {
    VOXC_ASSERT(validShape(points) && (solid & ~points) == 0);
    const std::vector<std::vector<int>> rings = facets(points);

    // The segments: on each ring, a run of solid points is cut off by a segment from the crossing
    // where the ring enters it to the crossing where it leaves, so the solid lies to the segment's
    // right seen from outside (the regular table's orientation: loops counter-clockwise seen from air).
    std::array<int, kSubEdgeIds> next;
    next.fill(-1);
    std::array<std::vector<int>, kSubEdgeIds> facetsOf;
    for (size_t f = 0; f < rings.size(); ++f) {
        const std::vector<int>& ring = rings[f];
        const size_t n = ring.size();
        auto isSolid = [&](size_t i) { return bool((solid >> ring[i % n]) & 1u); };
        auto edgeAfter = [&](size_t i) { return subEdgeId(subEdgeBetween(ring[i % n], ring[(i + 1) % n])); };
        for (size_t i = 0; i < n; ++i) facetsOf[size_t(edgeAfter(i))].push_back(int(f));
        for (size_t i = 0; i < n; ++i) {
            if (!isSolid(i) || isSolid(i + n - 1)) continue; // not where a solid run starts (an all-solid ring has none)
            size_t j = i;
            while (isSolid(j + 1)) ++j;
            const int from = edgeAfter(i + n - 1), to = edgeAfter(j);
            VOXC_ASSERT(next[size_t(from)] == -1);
            next[size_t(from)] = to;
        }
    }

    CellTriangles result;
    std::array<bool, kSubEdgeIds> used{};
    for (int start = 0; start < kSubEdgeIds; ++start) {
        if (next[size_t(start)] < 0 || used[size_t(start)]) continue;
        std::vector<int> loop;
        for (int e = start; !used[size_t(e)]; e = next[size_t(e)]) {
            VOXC_ASSERT(next[size_t(e)] >= 0); // a crossed sub-edge leaves on its second facet
            used[size_t(e)] = true;
            loop.push_back(e);
        }
        VOXC_ASSERT(next[size_t(loop.back())] == start);

        // Optimal triangulation of the loop: no chord between two vertices on one face of the cube
        // (a chord inside the cell is this cell's alone), no triangle whose vertices are collinear at the
        // sub-edges' midpoints (where binary 0/1 samples put them: a loop along a refined face can
        // run straight through several), then the least total chord length.
        // A chord another cell can hold too: both vertices on one facet (the cell across it), on
        // one cube edge line (the cells around it, coarse ones holding the whole line), or in one
        // face that is not refined (the coarse cell across it). A refined face's other cells are
        // fine and each holds one of its squares, so a chord across two squares is this cell's.
        auto shared = [&](int a, int b) {
            for (int f : facetsOf[size_t(a)])
                if (std::find(facetsOf[size_t(b)].begin(), facetsOf[size_t(b)].end(), f) != facetsOf[size_t(b)].end()) return true;
            const SubEdge ea = subEdgeOf(a), eb = subEdgeOf(b);
            const glm::ivec3 pa = pointOffset(ea.lower), pb = pointOffset(eb.lower);
            int sharedBoundaryPlanes = 0;
            for (int axis = 0; axis < 3; ++axis) {
                if (axis == ea.axis || axis == eb.axis || pa[axis] != pb[axis] || pa[axis] == 1) continue;
                ++sharedBoundaryPlanes;
                glm::ivec3 centre(1);
                centre[axis] = pa[axis];
                if (!present(points, centre)) return true; // one face, not refined
            }
            return sharedBoundaryPlanes == 2; // one cube edge line
        };
        const auto triangles = mesh_tables::triangulateLoop(
            loop.size(),
            [&](size_t i, size_t j) {
                if (shared(loop[i], loop[j])) return std::numeric_limits<float>::infinity();
                return glm::length(midpoint(subEdgeOf(loop[i])) - midpoint(subEdgeOf(loop[j])));
            },
            [&](size_t i, size_t k, size_t j) {
                const glm::vec3 pi = midpoint(subEdgeOf(loop[i]));
                return glm::cross(midpoint(subEdgeOf(loop[k])) - pi, midpoint(subEdgeOf(loop[j])) - pi) != glm::vec3(0.0f);
            });
        if (!triangles) {
            // No triangulation keeps to this cell: fan the loop around a vertex at its centre.
            const int8_t centre = int8_t(result.centredLoops.size());
            std::vector<SubEdge>& members = result.centredLoops.emplace_back();
            for (int e : loop) members.push_back(subEdgeOf(e));
            for (size_t i = 0; i < members.size(); ++i)
                for (CellVertex corner : {CellVertex{{}, centre}, CellVertex{members[i]}, CellVertex{members[(i + 1) % members.size()]}})
                    result.corners.push_back(corner);
            continue;
        }
        for (const auto& triangle : *triangles)
            for (size_t corner : triangle) result.corners.push_back(CellVertex{subEdgeOf(loop[corner])});
    }
    return result;
}

} // namespace voxc::transition_cells

// The marching-cubes case table, derived rather than typed in. Each cell face is cut on its own:
// a face with two crossed edges by one segment, an ambiguous face (solid corners diagonal) by
// two segments that cut off its two solid corners. Both cells sharing a face see the same four
// samples and apply the same rule, so their cuts agree and the surface has no holes (the flaw of
// tables built by complement symmetry). Segments are oriented with the solid on a fixed side,
// chained into loops through the crossed edges (every crossed edge lies on exactly two faces),
// and each loop is triangulated without a chord between two vertices on one face, so no edge
// is shared by more than the two triangles on either side of it.
#include "voxc/mesh/MarchingCubes.h"

#include "LoopTriangulation.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

namespace voxc::marching_cubes {
namespace {

struct Face {
    int axis;
    int side;
    std::array<int, 4> corners; // in order around the face
};

Face cellFace(int face) {
    const int axis = face / 2, side = face % 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    Face f{axis, side, {}};
    const glm::ivec2 ring[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) f.corners[size_t(k)] = side << axis | ring[k].x << u | ring[k].y << v;
    return f;
}

int edgeBetween(int a, int b) {
    for (int e = 0; e < 12; ++e) {
        const std::array<int, 2> c = edgeCorners(e);
        if ((c[0] == a && c[1] == b) || (c[0] == b && c[1] == a)) return e;
    }
    throw InternalError("marching cubes: corners are not adjacent");
}

glm::vec3 edgeMidpoint(int edge) {
    const std::array<int, 2> c = edgeCorners(edge);
    return 0.5f * glm::vec3(cornerOffset(c[0]) + cornerOffset(c[1]));
}

bool solidCorner(unsigned mask, int corner) { return (mask >> corner) & 1u; }

// Directed segments of one case: segment a -> b runs so that, seen from outside the cell, the
// solid lies to its right (this makes the loops counter-clockwise seen from the air side).
std::array<int, 12> faceSegments(unsigned mask) {
    std::array<int, 12> next;
    next.fill(-1);
    auto add = [&](int face, int a, int b) {
        const Face f = cellFace(face);
        glm::vec3 outward(0.0f);
        outward[f.axis] = f.side ? 1.0f : -1.0f;
        const std::array<int, 2> ac = edgeCorners(a);
        const glm::vec3 solidOfA(cornerOffset(solidCorner(mask, ac[0]) ? ac[0] : ac[1]));
        const glm::vec3 pa = edgeMidpoint(a), pb = edgeMidpoint(b);
        if (glm::dot(glm::cross(outward, pb - pa), solidOfA - pa) > 0.0f) std::swap(a, b);
        VOXC_ASSERT(next[size_t(a)] == -1);
        next[size_t(a)] = b;
    };
    for (int face = 0; face < 6; ++face) {
        const Face f = cellFace(face);
        int crossed[4], count = 0;
        for (int k = 0; k < 4; ++k) {
            const int a = f.corners[size_t(k)], b = f.corners[size_t((k + 1) % 4)];
            if (solidCorner(mask, a) != solidCorner(mask, b)) crossed[count++] = edgeBetween(a, b);
        }
        if (count == 2) add(face, crossed[0], crossed[1]);
        if (count == 4) {
            // Ambiguous: cut off each solid corner with the two crossed edges that meet at it.
            for (int k = 0; k < 4; ++k) {
                const int corner = f.corners[size_t(k)];
                if (!solidCorner(mask, corner)) continue;
                add(face, edgeBetween(f.corners[size_t((k + 3) % 4)], corner), edgeBetween(corner, f.corners[size_t((k + 1) % 4)]));
            }
        }
    }
    return next;
}

bool shareFace(int a, int b) {
    for (int face = 0; face < 6; ++face) {
        const Face f = cellFace(face);
        int on = 0;
        for (int k = 0; k < 4; ++k) {
            const int e = edgeBetween(f.corners[size_t(k)], f.corners[size_t((k + 1) % 4)]);
            on += (e == a) + (e == b);
        }
        if (on == 2) return true;
    }
    return false;
}

// Triangulates a loop: no chord joins two vertices on one face, which the neighbouring cell could
// use as well; among the rest the shortest total chord length between edge midpoints, so
// triangles stay well shaped.
void triangulateLoop(const std::vector<int>& loop, CellCase& out) {
    const auto triangles = mesh_tables::triangulateLoop(
        loop.size(),
        [&](size_t i, size_t j) {
            if (shareFace(loop[i], loop[j])) return std::numeric_limits<float>::infinity();
            return glm::length(edgeMidpoint(loop[i]) - edgeMidpoint(loop[j]));
        },
        [](size_t, size_t, size_t) { return true; });
    if (!triangles) throw InternalError("marching cubes: a loop has no triangulation without face chords");
    for (const auto& triangle : *triangles) {
        VOXC_ASSERT(out.triangleCount < kMaxTrianglesPerCell);
        const size_t base = size_t(out.triangleCount) * 3;
        for (size_t c = 0; c < 3; ++c) out.edges[base + c] = uint8_t(loop[triangle[c]]);
        ++out.triangleCount;
    }
}

CellCase deriveCase(unsigned mask) {
    const std::array<int, 12> next = faceSegments(mask);
    CellCase result;
    std::array<bool, 12> used{};
    for (int start = 0; start < 12; ++start) {
        if (next[size_t(start)] < 0 || used[size_t(start)]) continue;
        std::vector<int> loop;
        for (int e = start; !used[size_t(e)]; e = next[size_t(e)]) {
            VOXC_ASSERT(next[size_t(e)] >= 0); // every crossed edge leaves on its second face
            used[size_t(e)] = true;
            loop.push_back(e);
        }
        VOXC_ASSERT(loop.front() == start && next[size_t(loop.back())] == start);
        triangulateLoop(loop, result);
    }
    return result;
}

std::array<CellCase, 256> deriveTable() {
    std::array<CellCase, 256> table;
    for (unsigned mask = 0; mask < 256; ++mask) table[mask] = deriveCase(mask);
    return table;
}

} // namespace

std::array<int, 2> edgeCorners(int edge) {
    const int axis = edge / 4, k = edge % 4, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int lower = (k & 1) << u | (k >> 1) << v;
    return {lower, lower | 1 << axis};
}

const std::array<CellCase, 256>& caseTable() {
    static const std::array<CellCase, 256> table = deriveTable();
    return table;
}

float crossingMargin(const ChunkLayout& layout) {
    const glm::ivec3 far = glm::max(glm::abs(layout.gridOrigin - 1), glm::abs(layout.gridOrigin + layout.gridSize));
    const float largest = float(std::max({far.x, far.y, far.z}));
    const float spacing = std::nextafter(largest, INFINITY) - largest;
    return std::clamp(16.0f * spacing, kCrossingMargin, 0.125f);
}

float crossing(float d0, float d1, float iso, float margin) {
    // In double: iso lies between the samples, so t is in [0, 1] even where the float difference
    // of far-apart samples would overflow.
    const float t = float((double(iso) - d0) / (double(d1) - d0));
    return std::clamp(t, margin, 1.0f - margin);
}

} // namespace voxc::marching_cubes

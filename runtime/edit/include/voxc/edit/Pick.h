#pragma once
// The ray pick: the first point where a ray enters solid, on the field the meshers see (meshing
// spec §1.7 #12), not the centre of a voxel.
//
// The field is the trilinear interpolation of the samples (outside the grid, and densities that are
// not finite, read 0 as for the meshers); solid is > iso. The ray is marched in steps of 1/8 voxel
// from where it enters the grid's box grown by one voxel (beyond it everything is air), and the
// first step that lands in solid is refined by bisection on the ray parameter, in double, to the
// iso crossing. Inside a cell the trilinear field bends a curved surface by up to h^2 tr(H) / 8, so
// the hit is then moved onto a quadratic height field fitted to the grid-edge crossings around it
// (the meshers' vertices, each off by one axis' h^2 / (8 R)) where the ray meets it, unless the
// fit is undetermined or would move it by 0.25 voxel or more (src/Pick.cpp). A solid feature
// thinner than the step along the ray can be stepped over.
#include "voxc/grid/Grid.h"

#include <glm/vec3.hpp>
#include <optional>

namespace voxc {

struct PickHit {
    float t = 0.0f;       // distance along the (normalised) direction
    glm::vec3 point{0.0f};
    bool inside = false;  // the ray starts in solid: t = 0, point = origin
};

// nullopt when the ray meets no solid within maxDistance (or the direction is zero or not finite).
std::optional<PickHit> pick(const ChunkedGrid& grid, float iso, glm::vec3 origin, glm::vec3 direction,
                            float maxDistance = 1e30f);

// The trilinear field at a world position (exposed for the tests).
double sampleField(const ChunkedGrid& grid, glm::dvec3 p);

} // namespace voxc

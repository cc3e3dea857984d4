// The least-weight triangulation of a closed loop of cell vertices, shared by the marching-cubes
// table and the transition cells so both derive their cases by one rule.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace voxc::mesh_tables {

// Chord (i, j) of the loop, i < j and not a side: its length, or infinity where another cell could
// hold the same chord (a forbidden chord).
using ChordCost = std::function<float(size_t i, size_t j)>;
// Whether triangle (i, k, j), i < k < j, may appear at all (a degenerate one may not).
using TriangleAllowed = std::function<bool(size_t i, size_t k, size_t j)>;

// Optimal over all triangulations (interval dynamic programming; loops have at most a few dozen
// vertices): the least total chord cost. Triangles come as loop-index triples in a fixed order (left
// part, the splitting triangle, right part); none for a loop of fewer than three vertices. No value
// when every triangulation needs a forbidden chord.
std::optional<std::vector<std::array<size_t, 3>>> triangulateLoop(size_t n, const ChordCost& chordCost,
                                                                  const TriangleAllowed& allowed);

} // namespace voxc::mesh_tables

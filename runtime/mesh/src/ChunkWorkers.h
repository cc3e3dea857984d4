#pragma once
// Running a mesher's chunks on worker threads.
#include "voxc/grid/Grid.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace voxc {

// World chunks holding at least one cell (cells start one voxel below the grid), z slowest.
std::vector<glm::ivec3> cellChunks(const ChunkLayout& layout);

// Calls work(i) for i in [0, count) on up to hardware_concurrency threads, in any order; work
// returns false for a chunk it skipped. Rethrows the first failure after every thread has stopped.
// Returns the number of skipped chunks.
size_t forEachChunk(size_t count, const std::function<bool(size_t)>& work);

} // namespace voxc

#include "ChunkWorkers.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>

namespace voxc {

std::vector<glm::ivec3> cellChunks(const ChunkLayout& layout) {
    const glm::ivec3 first = (layout.gridOrigin - 1) >> layout.chunkShift;
    const glm::ivec3 last = (layout.gridOrigin + layout.gridSize - 1) >> layout.chunkShift;
    std::vector<glm::ivec3> chunks;
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) chunks.push_back({x, y, z});
    return chunks;
}

size_t forEachChunk(size_t count, const std::function<bool(size_t)>& work) {
    std::atomic<size_t> next{0}, skipped{0};
    const size_t workerCount = std::max<size_t>(1, std::min<size_t>(std::thread::hardware_concurrency(), count));
    std::vector<std::exception_ptr> failures(workerCount);
    auto run = [&](size_t worker) {
        try {
            for (size_t i = next++; i < count; i = next++)
                if (!work(i)) ++skipped;
        } catch (...) {
            failures[worker] = std::current_exception();
            next = count;
        }
    };
    std::vector<std::thread> workers;
    for (size_t w = 1; w < workerCount; ++w) workers.emplace_back(run, w);
    run(0);
    for (std::thread& t : workers) t.join();
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
    return skipped;
}

} // namespace voxc

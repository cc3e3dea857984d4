#include "HeapReuse.h"

#include "voxc/core/HugePages.h"

#include <cstdlib>
#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>

namespace voxc::curves {

namespace {

// Solves in progress (several may run on different threads); the settings change at 0 <-> 1.
std::mutex gMutex;
int gActive = 0;

#if defined(__GLIBC__)
constexpr int kSolveThreshold = 1 << 30;          // every field from the heap
constexpr int kAdaptiveMmapCeiling = 32 << 20;    // glibc's DEFAULT_MMAP_THRESHOLD_MAX (64-bit)
constexpr int kAdaptiveTrimCeiling = 2 * kAdaptiveMmapCeiling; // the trim threshold it sets beside it
// The heap a solve touches per box cell (measured peak at 256x128x256: about 80 bytes), capped
// under the solve's mmap threshold so the reservation comes from the heap.
constexpr uint64_t kBytesPerCell = 80, kMaxReserve = 900ull << 20;
constexpr uintptr_t kHugePage = 2u << 20;

// Grows the heap by about `bytes` without touching it (malloc writes only the chunk's header and
// free returns it to the top of the heap, which the raised trim threshold keeps) and asks for
// huge pages over it; the solve's fields are then carved from it.
void reserveHugePages(uint64_t bytes) {
    if (bytes < 4 * kHugePage) return;
    void* block = std::malloc(size_t(bytes));
    if (!block) return;
    adviseHugePages(block, size_t(bytes));
    std::free(block);
}
#endif

} // namespace

FieldHeapReuse::FieldHeapReuse(uint64_t cells) {
    const std::lock_guard lock(gMutex);
#if defined(__GLIBC__)
    if (gActive == 0) {
        mallopt(M_MMAP_THRESHOLD, kSolveThreshold);
        mallopt(M_TRIM_THRESHOLD, kSolveThreshold);
        reserveHugePages(std::min(cells * kBytesPerCell, kMaxReserve));
    }
#else
    (void)cells;
#endif
    ++gActive;
}

FieldHeapReuse::~FieldHeapReuse() {
    const std::lock_guard lock(gMutex);
    if (--gActive > 0) return;
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, kAdaptiveMmapCeiling);
    mallopt(M_TRIM_THRESHOLD, kAdaptiveTrimCeiling);
    malloc_trim(0);
#endif
}

} // namespace voxc::curves

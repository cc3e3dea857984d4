#include "HeapReuse.h"

#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace voxc::curves {

namespace {

// Solves in progress (several may run on different threads); the settings change at 0 <-> 1.
std::mutex gMutex;
int gActive = 0;

#if defined(__GLIBC__)
constexpr int kSolveThreshold = 1 << 30;          // every field from the heap
constexpr int kAdaptiveMmapCeiling = 32 << 20;    // glibc's DEFAULT_MMAP_THRESHOLD_MAX (64-bit)
constexpr int kAdaptiveTrimCeiling = 2 * kAdaptiveMmapCeiling; // the trim threshold it sets beside it
#endif

} // namespace

FieldHeapReuse::FieldHeapReuse() {
    const std::lock_guard lock(gMutex);
#if defined(__GLIBC__)
    if (gActive == 0) {
        mallopt(M_MMAP_THRESHOLD, kSolveThreshold);
        mallopt(M_TRIM_THRESHOLD, kSolveThreshold);
    }
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

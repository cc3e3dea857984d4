#pragma once
// Buffers larger than glibc's mmap threshold (the host mesher's sign bits and mesh arrays, a curves
// solve's heap) are fresh mappings whose first touches fault in each 4 KiB page (about 10,000
// faults for a 512^3 grid's mesh, at several microseconds each in a virtual machine). Marked for
// transparent huge pages before the first touch (MADV_HUGEPAGE; the kernel's default mode
// "madvise" gives them only where asked) they fault in 2 MiB at a time. Elsewhere than Linux this
// does nothing.
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace voxc {

// Asks for huge pages over the whole 2 MiB pages inside [data, data + bytes) (advice: may fail).
inline void adviseHugePages(void* data, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr uintptr_t kHugePage = uintptr_t(2) << 20;
    if (bytes < 2 * kHugePage) return;
    const uintptr_t first = (uintptr_t(data) + kHugePage - 1) & ~(kHugePage - 1);
    const uintptr_t last = (uintptr_t(data) + bytes) & ~(kHugePage - 1);
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

// Sizes an empty vector to n elements, its storage advised for huge pages before it is written.
template <class T> void resizeOnHugePages(std::vector<T>& v, size_t n) {
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
    v.resize(n);
}

} // namespace voxc

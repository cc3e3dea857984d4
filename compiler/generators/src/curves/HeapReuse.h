#pragma once
// While a curves solve (or the check's voxelisation) runs, the fields it frees (32 MiB each at 256x128x256) go back to the heap
// for the next field instead of to the kernel. glibc maps every allocation over its mmap
// threshold (adaptive, at most 32 MiB) afresh, so every field was a fresh mapping whose first
// touch faulted in each of its pages (8,193 faults per 32 MiB field); reused from the heap it costs
// none. The heap the solve will fill is reserved at its start and marked for transparent huge
// pages (MADV_HUGEPAGE; the kernel's default mode "madvise" gives them only where asked), so
// its first touches fault in 2 MiB at a time instead of 4 KiB: a 256x128x256 solve touches about
// 650 MiB, 166,000 small-page faults. When the last solve in the process ends, the thresholds go
// to what glibc's adaptive rule reaches after one such field (mmap 32 MiB, trim 64 MiB) and
// malloc_trim hands the freed memory back, so a long-running process (the language server, the
// viewer) does not keep its largest solve's memory. Elsewhere than glibc on Linux it does nothing.
#include <cstdint>

namespace voxc::curves {

class FieldHeapReuse {
public:
    // `cells`: the solve box's cell count, which sizes the heap reserved for huge pages.
    explicit FieldHeapReuse(uint64_t cells);
    ~FieldHeapReuse();
    FieldHeapReuse(const FieldHeapReuse&) = delete;
    FieldHeapReuse& operator=(const FieldHeapReuse&) = delete;
};

} // namespace voxc::curves

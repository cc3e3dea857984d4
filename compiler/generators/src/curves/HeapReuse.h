#pragma once
// While a curves solve runs, the fields it frees (32 MiB each at 256x128x256) go back to the heap
// for the next field instead of to the kernel. glibc maps every allocation over its mmap
// threshold (adaptive, at most 32 MiB) afresh, so every field was a fresh mapping whose first
// touch faulted in each of its pages (8,193 faults per 32 MiB field); reused from the heap it costs
// none. When the last solve in the process ends, the thresholds go to what glibc's adaptive rule
// reaches after one such field (mmap 32 MiB, trim 64 MiB) and malloc_trim hands the freed memory
// back, so a long-running process (the language server, the viewer) does not keep its largest
// solve's memory. Elsewhere than glibc it does nothing.

namespace voxc::curves {

class FieldHeapReuse {
public:
    FieldHeapReuse();
    ~FieldHeapReuse();
    FieldHeapReuse(const FieldHeapReuse&) = delete;
    FieldHeapReuse& operator=(const FieldHeapReuse&) = delete;
};

} // namespace voxc::curves

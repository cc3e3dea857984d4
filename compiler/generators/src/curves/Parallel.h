#pragma once
// Splits the z slices of a box between two threads for passes whose per-cell results do not
// depend on the order cells are visited (pointwise maps, one red-black colour), so the result is
// the same bits as one thread's loop; and runs two independent parts side by side.
#include <cstdint>
#include <exception>
#include <thread>

namespace voxc::curves {

// Runs `first` on a second thread and `second` on this one; rethrows what either threw.
template <typename First, typename Second>
void bothOf(First&& first, Second&& second) {
    std::exception_ptr failed;
    std::thread other([&] {
        try {
            first();
        } catch (...) {
            failed = std::current_exception();
        }
    });
    try {
        second();
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (failed) std::rethrow_exception(failed);
}

// Calls slab(z0, z1) for [0, mid) on a second thread and [mid, count) on this one; small counts
// (under `minimum`) run on this thread alone. `slab` must only write cells of its own slices.
template <typename Slab>
void forTwoSlabs(int32_t count, int32_t minimum, Slab&& slab) {
    if (count < minimum || count < 2) return slab(0, count);
    const int32_t mid = count / 2;
    bothOf([&] { slab(0, mid); }, [&] { slab(mid, count); });
}

} // namespace voxc::curves

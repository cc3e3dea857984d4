#pragma once
// A long computation (a curves or terrain solve) asked through its std::stop_token to stop: it
// stops at its next boundary (a V-cycle, a pass, a batch of erosion steps) and leaves no result.
// Neither the user's fault nor a bug (voxc/core/Errors.h): whoever asked expects it.
#include <stdexcept>
#include <stop_token>

namespace voxc {

struct Stopped : std::runtime_error {
    Stopped() : std::runtime_error("stopped before it finished") {}
};

inline void throwIfStopped(const std::stop_token& stop) {
    if (stop.stop_requested()) throw Stopped();
}

} // namespace voxc

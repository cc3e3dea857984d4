#pragma once
// Two kinds of failure, kept apart as in Halide: a UserError is the user's fault
// (bad file, bad flag, no device) and exits 1; an InternalError is a voxc bug and exits 2.
#include <stdexcept>
#include <string>

namespace voxc {

struct UserError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct InternalError : std::logic_error {
    using std::logic_error::logic_error;
};

[[noreturn]] void internalError(const char* file, int line, const std::string& what);

} // namespace voxc

#define VOXC_ASSERT(cond)                                                  \
    do {                                                                   \
        if (!(cond)) ::voxc::internalError(__FILE__, __LINE__, #cond);     \
    } while (0)

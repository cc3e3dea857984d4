#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc {

void internalError(const char* file, int line, const std::string& what) {
    throw InternalError(fmt::format("internal error at {}:{}: {}", file, line, what));
}

} // namespace voxc

#include "voxc/core/AtomicWrite.h"

#include "voxc/core/Errors.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

namespace voxc {

void internalError(const char* file, int line, const std::string& what) {
    throw InternalError(fmt::format("internal error at {}:{}: {}", file, line, what));
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    namespace fs = std::filesystem;
    fs::path target(path);
    fs::path temp = target;
    temp += fmt::format(".tmp{}", ::getpid());
    try {
        {
            std::ofstream out(temp, std::ios::binary | std::ios::trunc);
            if (!out) throw UserError(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
            write(out);
            out.flush();
            if (!out) throw UserError(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
        }
        std::error_code ec;
        fs::rename(temp, target, ec);
        if (ec) throw UserError(fmt::format("cannot write '{}': {}", path, ec.message()));
    } catch (...) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw;
    }
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
    writeFileAtomically(path, [&](std::ostream& out) { out.write(contents.data(), std::streamsize(contents.size())); });
}

} // namespace voxc

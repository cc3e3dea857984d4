#include "voxc/core/InputFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace voxc {

namespace {

// What kind of file a stat describes, for the message refusing it.
std::string_view kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    return "not a regular file";
}

InputFileRead failure(const std::string& path, InputFileProblem problem, std::string_view why) {
    return {std::nullopt, problem, fmt::format("cannot read file '{}': {}", path, why)};
}

InputFileRead fromErrno(const std::string& path, int error) {
    if (error == ENOENT || error == ENOTDIR) return failure(path, InputFileProblem::Missing, "no such file");
    return failure(path, InputFileProblem::Unreadable, std::strerror(error));
}

InputFileRead tooLarge(const std::string& path, uint64_t maxBytes) {
    const std::string mebibytes = maxBytes >= (uint64_t(1) << 20) ? fmt::format(" ({} MiB)", maxBytes >> 20) : "";
    return failure(path, InputFileProblem::TooLarge,
                   fmt::format("it is larger than the limit of {} bytes{}", maxBytes, mebibytes));
}

class Fd {
public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

// Reads up to `maxBytes + 1` bytes in blocks: one byte past the cap tells a file that grew, or
// a stream, from one that fits.
InputFileRead readCapped(const std::string& path, int fd, uint64_t maxBytes) {
    std::string bytes;
    char block[1 << 16];
    while (bytes.size() <= maxBytes) {
        const size_t want = size_t(std::min<uint64_t>(sizeof block, maxBytes + 1 - bytes.size()));
        const ssize_t got = ::read(fd, block, want);
        if (got < 0) {
            if (errno == EINTR) continue;
            return fromErrno(path, errno);
        }
        if (got == 0) break;
        bytes.append(block, size_t(got));
    }
    if (bytes.size() > maxBytes) return tooLarge(path, maxBytes);
    return {std::move(bytes), InputFileProblem::None, {}};
}

InputFileRead read(const std::string& path, uint64_t maxBytes, bool regularOnly) {
    // stat first, so that a device is not even opened; fstat again on what was opened, in case
    // the path changed in between.
    struct stat before {};
    if (::stat(path.c_str(), &before) != 0) return fromErrno(path, errno);
    if (S_ISDIR(before.st_mode) || (regularOnly && !S_ISREG(before.st_mode)))
        return failure(path, InputFileProblem::NotRegular, fmt::format("it is {}, not a regular file", kindOf(before.st_mode)));
    const int flags = O_RDONLY | O_CLOEXEC | O_NOCTTY | (regularOnly ? O_NONBLOCK : 0);
    const Fd fd(::open(path.c_str(), flags));
    if (fd.get() < 0) return fromErrno(path, errno);
    struct stat opened {};
    if (::fstat(fd.get(), &opened) != 0) return fromErrno(path, errno);
    if (S_ISDIR(opened.st_mode) || (regularOnly && !S_ISREG(opened.st_mode)))
        return failure(path, InputFileProblem::NotRegular, fmt::format("it is {}, not a regular file", kindOf(opened.st_mode)));
    if (S_ISREG(opened.st_mode) && uint64_t(opened.st_size) > maxBytes) return tooLarge(path, maxBytes);
    return readCapped(path, fd.get(), maxBytes);
}

} // namespace

InputFileRead readInputFile(const std::string& path, uint64_t maxBytes) { return read(path, maxBytes, true); }

InputFileRead readCommandLineFile(const std::string& path, uint64_t maxBytes) { return read(path, maxBytes, false); }

} // namespace voxc

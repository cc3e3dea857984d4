#include "ExistingPackage.h"

#include "voxc/codegen/PackageWriter.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <cerrno>
#include <algorithm>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace voxc::codegen {

namespace {

namespace fs = std::filesystem;

// A file of the directory being read disappeared: a concurrent compile swapped the package out
// and is removing it.
struct Vanished {};

// Why the directory cannot be used, said by existingPackage for its verb. `notAPackage`: the
// directory is not a voxc package, which replacing it would delete.
struct Refused {
    std::string why;
    bool notAPackage = false;
};

[[noreturn]] void refuse(const fs::path&, const std::string& why) { throw Refused{why}; }

[[noreturn]] void failErrno(const fs::path& dir, const std::string& what) {
    if (errno == ENOENT) throw Vanished{};
    refuse(dir, fmt::format("cannot read {}: {}", what, std::strerror(errno)));
}

[[noreturn]] void foreign(const std::string& relative) {
    throw Refused{fmt::format("the directory is not a voxc package: voxc did not write '{}'", relative), true};
}

class Fd {
public:
    explicit Fd(int fd) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }

private:
    int fd_;
};

// What one file of a package, and all of them together, may hold: far above what voxc writes (a
// kernel's SPIR-V is kilobytes, an lsystem_cave's point sets at most 2^24 list entries of 4 bytes,
// a source 4 MiB), and checked from the file's size before a byte is read, so a tampered or
// foreign file of gigabytes is refused at once instead of read whole.
constexpr uint64_t kMaxPackageFileBytes = uint64_t(256) << 20;
constexpr uint64_t kMaxPackageBytes = uint64_t(1) << 30;

// An open file of the package, its size from fstat, before a byte is read.
struct OpenFile {
    int fd;
    uint64_t size;
};

OpenFile openAt(const fs::path& dir, int dirFd, const std::string& name, const std::string& shown, int& fd) {
    fd = ::openat(dirFd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) failErrno(dir, shown);
    struct stat st {};
    if (::fstat(fd, &st) != 0) failErrno(dir, shown);
    if (!S_ISREG(st.st_mode)) foreign(shown);
    return {fd, uint64_t(st.st_size)};
}

std::string readOpen(const fs::path& dir, const OpenFile& file, const std::string& shown, uint64_t& packageBytes) {
    const uint64_t size = file.size;
    if (size > kMaxPackageFileBytes)
        refuse(dir, fmt::format("{} is {} bytes, more than a package file may hold ({} bytes); the package is corrupt",
                              shown, size, kMaxPackageFileBytes));
    packageBytes += size;
    if (packageBytes > kMaxPackageBytes)
        refuse(dir, fmt::format("its files pass {} bytes at {}; the package is corrupt", kMaxPackageBytes, shown));
    std::string bytes;
    char buffer[65536];
    for (;;) {
        // One byte past the size fstat gave tells a file that grew while read.
        const size_t want = size_t(std::min<uint64_t>(sizeof buffer, size + 1 - bytes.size()));
        const ssize_t n = ::read(file.fd, buffer, want);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) failErrno(dir, shown);
        if (n == 0) return bytes;
        bytes.append(buffer, size_t(n));
        if (bytes.size() > size) refuse(dir, fmt::format("{} grew while voxc read it", shown));
    }
}

std::string readAt(const fs::path& dir, int dirFd, const std::string& name, const std::string& shown,
                   uint64_t& packageBytes) {
    int raw = -1;
    const OpenFile file = openAt(dir, dirFd, name, shown, raw);
    const Fd fd(raw);
    return readOpen(dir, file, shown, packageBytes);
}

// The byte count manifest.json gives each file of the package ("files"; empty when it gives none).
std::map<std::string, uint64_t> manifestFileSizes(const std::string& manifestText) {
    std::map<std::string, uint64_t> sizes;
    const nlohmann::json manifest = nlohmann::json::parse(manifestText, nullptr, /*allow_exceptions=*/false);
    if (!manifest.is_object()) return sizes;
    const auto files = manifest.find("files");
    if (files == manifest.end() || !files->is_object()) return sizes;
    for (const auto& [path, bytes] : files->items())
        if (bytes.is_number_unsigned()) sizes[path] = bytes.get<uint64_t>();
    return sizes;
}

struct Entry {
    std::string name;
    mode_t type; // S_IFREG, S_IFDIR, S_IFLNK, ...
};

// The entries of an open directory, "." and ".." left out; `dirFd` stays open.
std::vector<Entry> listAt(const fs::path& dir, int dirFd, const std::string& shown) {
    DIR* stream = ::fdopendir(::dup(dirFd));
    if (!stream) failErrno(dir, shown);
    std::vector<Entry> entries;
    while (const dirent* e = ::readdir(stream)) {
        const std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        struct stat st {};
        if (::fstatat(dirFd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
            ::closedir(stream);
            failErrno(dir, shown + name);
        }
        entries.push_back({name, mode_t(st.st_mode & S_IFMT)});
    }
    ::closedir(stream);
    return entries;
}

bool isVoxcManifest(const std::string& text) {
    const nlohmann::json manifest = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!manifest.is_object()) return false;
    // Packages written before the manifest had a format key carry only voxc_version.
    return manifest.value("format", "") == kPackageFormat || manifest.contains("voxc_version");
}

std::optional<std::map<std::string, std::string>> readPackage(const fs::path& dir, PackageVerb verb) {
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0) {
        if (errno == ENOENT) return std::nullopt;
        refuse(dir, std::strerror(errno));
    }
    if (S_ISLNK(st.st_mode)) refuse(dir, "it is a symbolic link; give the directory it points to");
    if (!S_ISDIR(st.st_mode)) refuse(dir, "it exists and is not a directory");
    const Fd dirFd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (dirFd.get() < 0) failErrno(dir, "the directory");

    std::map<std::string, std::string> files;
    uint64_t packageBytes = 0;
    const std::vector<Entry> entries = listAt(dir, dirFd.get(), "");
    // manifest.json first: the size it gives each file is checked before that file is read.
    std::map<std::string, uint64_t> expectedSizes;
    for (const Entry& entry : entries)
        if (entry.name == "manifest.json" && entry.type == S_IFREG) {
            files[entry.name] = readAt(dir, dirFd.get(), entry.name, entry.name, packageBytes);
            expectedSizes = manifestFileSizes(files[entry.name]);
        }
    for (const Entry& entry : entries) {
        if (entry.name == "manifest.json" && entry.type == S_IFREG) {
            continue;
        } else if ((entry.name == "kernels" || entry.name == "data" || entry.name == "sources") &&
                   entry.type == S_IFDIR) {
            // kernels/*.comp and *.spv; data/*.bin; sources/*.vox, *.rules and input files' copies
            const std::string sub = entry.name + "/";
            const Fd subFd(::openat(dirFd.get(), entry.name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
            if (subFd.get() < 0) failErrno(dir, sub);
            for (const Entry& file : listAt(dir, subFd.get(), sub)) {
                const std::string relative = sub + file.name;
                const std::string extension = fs::path(file.name).extension().string();
                const bool ours = entry.name == "kernels"   ? extension == ".comp" || extension == ".spv"
                                  : entry.name == "sources" ? extension == ".vox" || extension == ".rules" ||
                                                                  std::any_of(std::begin(kPackageInputExtensions),
                                                                              std::end(kPackageInputExtensions),
                                                                              [&](std::string_view known) {
                                                                                  return extension.substr(1) == known;
                                                                              })
                                                            : extension == ".bin";
                if (file.type != S_IFREG || !ours) foreign(relative);
                int raw = -1;
                const OpenFile open = openAt(dir, subFd.get(), file.name, relative, raw);
                const Fd fd(raw);
                const auto expected = expectedSizes.find(relative);
                if (expected != expectedSizes.end() && expected->second != open.size) {
                    // Not what voxc wrote: loading refuses it unread; writing replaces the package,
                    // which the missing entry tells the writer.
                    if (verb == PackageVerb::Load)
                        refuse(dir, fmt::format("{} is {} bytes and manifest.json says {}; the package is corrupt; compile it "
                                              "again with `voxc compile`",
                                              relative, open.size, expected->second));
                    continue;
                }
                files[relative] = readOpen(dir, open, relative, packageBytes);
            }
        } else {
            foreign(entry.name);
        }
    }
    if (!files.empty() && !(files.contains("manifest.json") && isVoxcManifest(files.at("manifest.json"))))
        throw Refused{"the directory is not a voxc package (it has no voxc manifest.json)", true};
    return files;
}

} // namespace

std::optional<std::map<std::string, std::string>> existingPackage(const fs::path& dir, PackageVerb verb) {
    const bool writing = verb == PackageVerb::Write;
    try {
        // Each retry follows a package that a concurrent compile swapped in; that takes that
        // compile's whole write, so a few retries outlast any realistic number of writers.
        constexpr int kAttempts = 16;
        for (int attempt = 0; attempt < kAttempts; ++attempt) {
            try {
                return readPackage(dir, verb);
            } catch (const Vanished&) {
            }
        }
        refuse(dir, "it keeps being replaced while voxc reads it");
    } catch (const Refused& refused) {
        throw UserError(fmt::format("cannot {} package '{}': {}{}", writing ? "write" : "load", dir.string(),
                                    refused.why,
                                    refused.notAPackage && writing ? ", and replacing the directory would delete it; "
                                                                     "remove it or choose another directory"
                                                                   : ""));
    }
}

} // namespace voxc::codegen

// The package directory is replaced as a whole: the new package is written into a sibling
// temp directory, synced, and swapped in with one rename, so readers and concurrent compiles
// only ever see whole packages.
#include "voxc/codegen/PackageWriter.h"

#include "ExistingPackage.h"
#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <optional>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace voxc::codegen {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& dir, const std::string& why) {
    throw UserError(fmt::format("cannot write package '{}': {}", dir.string(), why));
}

// The target as one absolute path without a trailing separator, however it was typed
// ("pkg", "./pkg/", "/abs/pkg" name the same directory).
fs::path normalDirectory(const std::string& dir) {
    if (dir.empty()) throw UserError("the package directory name is empty");
    fs::path path = fs::absolute(dir).lexically_normal();
    if (!path.has_filename()) path = path.parent_path();
    if (path == path.root_path()) fail(path, "it is the root directory");
    return path;
}

// Temp directories are named ".NAME.voxc-tmp.PID.RANDOM" beside the package.
std::string tempPrefix(const fs::path& dir) { return "." + dir.filename().string() + ".voxc-tmp."; }

// Removes temp directories that compiles into `dir` left behind when they were killed (SIGKILL,
// power loss, a signal during the write): those whose process no longer exists.
void removeAbandonedTempDirectories(const fs::path& dir) {
    const std::string prefix = tempPrefix(dir);
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir.parent_path(), error)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(prefix) || !entry.is_directory(error) || entry.is_symlink(error)) continue;
        const std::string rest = name.substr(prefix.size());
        const size_t dot = rest.find('.');
        if (dot == 0 || dot > 9 || dot == std::string::npos || rest.find_first_not_of("0123456789") != dot) continue;
        const pid_t pid = pid_t(std::stol(rest.substr(0, dot)));
        if (::kill(pid, 0) == -1 && errno == ESRCH) fs::remove_all(entry.path(), error);
    }
}

// A new, empty directory beside `dir`, created with the usual permissions (mkdir honours the umask).
// `cleanup` removes it on a signal and is armed before mkdir() makes it, so a signal between the
// two cannot leave it behind; a name another process holds is skipped without arming it.
fs::path createTempSibling(const fs::path& dir, CleanupEntry& cleanup) {
    std::random_device random;
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path temp =
            dir.parent_path() / fmt::format("{}{}.{:08x}", tempPrefix(dir), ::getpid(), uint32_t(random()));
        cleanup = CleanupEntry(temp.string());
        if (::access(temp.c_str(), F_OK) == 0) continue;
        cleanup.removeTreeOnSignal();
        if (::mkdir(temp.c_str(), 0777) == 0) return temp;
        const int mkdirError = errno;
        cleanup.ignoreOnSignal();
        if (mkdirError != EEXIST) fail(dir, fmt::format("cannot create a directory beside it: {}", std::strerror(mkdirError)));
    }
    fail(dir, "cannot find a free temp directory name beside it");
}

// Writes and syncs a new file: a full disk shows up here, before anything is renamed.
void writeNewFile(const fs::path& dir, const fs::path& path, const std::string& bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(dir, fmt::format("{}: {}", path.filename().string(), std::strerror(errno)));
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int writeError = errno;
            ::close(fd);
            fail(dir, fmt::format("{}: {}", path.filename().string(), std::strerror(writeError)));
        }
        written += size_t(n);
    }
    const bool synced = ::fsync(fd) == 0;
    const int syncError = errno;
    if (::close(fd) != 0 || !synced)
        fail(dir, fmt::format("{}: {}", path.filename().string(), std::strerror(synced ? errno : syncError)));
}

// Makes a rename inside `directory` durable.
void syncDirectory(const fs::path& directory) {
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

void writeTree(const fs::path& dir, const fs::path& temp, const std::map<std::string, std::string>& files) {
    for (const char* sub : {"kernels", "data", "sources"}) {
        const bool used = std::any_of(files.begin(), files.end(),
                                      [&](const auto& file) { return file.first.starts_with(std::string(sub) + "/"); });
        if (used && ::mkdir((temp / sub).c_str(), 0777) != 0) fail(dir, fmt::format("{}: {}", sub, std::strerror(errno)));
    }
    for (const auto& [relative, bytes] : files)
        writeNewFile(dir, temp / relative, bytes);
    for (const char* sub : {"kernels", "data", "sources"})
        if (fs::is_directory(temp / sub)) syncDirectory(temp / sub);
    syncDirectory(temp);
}

// Puts `temp` in place of `dir`. Returns false when `dir` was created meanwhile (by a concurrent
// compile) and must be exchanged instead.
bool renameIntoPlace(const fs::path& dir, const fs::path& temp) {
    if (::rename(temp.c_str(), dir.c_str()) == 0) return true;
    if (errno == EEXIST || errno == ENOTEMPTY) return false;
    fail(dir, std::strerror(errno));
}

// Swaps `temp` and the existing `dir` in one step; `temp` then names the old package, which is
// removed. Filesystems without RENAME_EXCHANGE get two renames (a reader may briefly find no
// directory, never a mixed one).
void exchangeIntoPlace(const fs::path& dir, const fs::path& temp) {
    if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
        if (errno != EINVAL && errno != ENOSYS) fail(dir, std::strerror(errno));
        CleanupEntry oldCleanup;
        const fs::path old = createTempSibling(dir, oldCleanup);
        oldCleanup.ignoreOnSignal(); // it is about to hold the previous package, which a signal keeps
        if (::rename(dir.c_str(), old.c_str()) != 0) {
            const int renameError = errno;
            ::rmdir(old.c_str());
            fail(dir, std::strerror(renameError));
        }
        if (::rename(temp.c_str(), dir.c_str()) != 0) {
            const int renameError = errno;
            ::rename(old.c_str(), dir.c_str());
            fail(dir, std::strerror(renameError));
        }
        std::error_code ignored;
        fs::remove_all(old, ignored);
        return;
    }
    std::error_code ignored;
    fs::remove_all(temp, ignored);
}

} // namespace

std::map<std::string, std::string> packageFiles(const KernelPackage& package, const PackageSource& source) {
    std::map<std::string, std::string> files;
    for (const Kernel& k : package.kernels) {
        files[packageGlslPath(k)] = k.glsl;
        files[packageSpirvPath(k)] = littleEndianWords(k.spirv);
    }
    for (const PackageData& data : packageData(package)) files[data.path] = littleEndianWords(data.words);
    if (!source.fileName.empty()) {
        files[packageSourcePath(0)] = source.text;
        for (size_t i = 0; i < source.imports.size(); ++i) files[packageSourcePath(i + 1, source.imports[i].path)] = source.imports[i].text;
    }
    files["manifest.json"] = packageManifest(package, source);
    return files;
}

PackageWrite writePackage(const KernelPackage& package, const std::string& dirName, const PackageSource& source) {
    const fs::path dir = normalDirectory(dirName);
    const std::map<std::string, std::string> files = packageFiles(package, source);
    const std::optional<std::map<std::string, std::string>> existing = existingPackage(dir);
    if (existing && *existing == files) return PackageWrite::Unchanged;

    std::error_code error;
    fs::create_directories(dir.parent_path(), error);
    if (error) fail(dir, fmt::format("cannot create {}: {}", dir.parent_path().string(), error.message()));
    removeAbandonedTempDirectories(dir);
    // Ctrl-C while the package is built or swapped removes the temp directory (after a swap it
    // holds the old package, which goes anyway).
    CleanupEntry cleanup;
    const fs::path temp = createTempSibling(dir, cleanup);
    try {
        writeTree(dir, temp, files);
        if (!existing) {
            if (renameIntoPlace(dir, temp)) {
                syncDirectory(dir.parent_path());
                return PackageWrite::Created;
            }
            existingPackage(dir); // refuses a foreign directory that appeared meanwhile
        }
        // The new package keeps the directory's permissions (a user may have opened it to a group).
        std::error_code ignored;
        fs::permissions(temp, fs::status(dir, ignored).permissions(), ignored);
        exchangeIntoPlace(dir, temp);
        syncDirectory(dir.parent_path());
        return PackageWrite::Replaced;
    } catch (...) {
        std::error_code ignored;
        fs::remove_all(temp, ignored);
        throw;
    }
}

} // namespace voxc::codegen

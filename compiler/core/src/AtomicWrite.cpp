#include "voxc/core/AtomicWrite.h"

#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>

namespace voxc {

namespace fs = std::filesystem;

namespace {

UserError cannotWrite(const std::string& path, const std::string& why) {
    return UserError(fmt::format("cannot write '{}': {}", path, why));
}

// "PATH.tmp-PID-N": the pid keeps processes apart, the counter threads and files of one process.
std::string siblingName(const fs::path& target) {
    static std::atomic<uint64_t> counter{0};
    return fmt::format("{}.tmp-{}-{}", target.string(), ::getpid(), counter++);
}

// A symlink is written through to the file it names; a dangling one is replaced itself.
fs::path resolveTarget(const std::string& path) {
    std::error_code ec;
    if (fs::is_symlink(path, ec)) {
        fs::path resolved = fs::canonical(path, ec);
        if (!ec) return resolved;
    }
    return fs::path(path);
}

// An ostream buffer on a file descriptor: the temp file is opened with O_EXCL and synced before
// the rename, which std::ofstream cannot do.
class FdBuffer : public std::streambuf {
public:
    explicit FdBuffer(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    int error() const { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = char(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* data, std::streamsize count) override {
        if (size_t(count) < buffer_.size()) return std::streambuf::xsputn(data, count);
        return drain() && writeAll(data, size_t(count)) ? count : 0; // big blocks skip the buffer
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const bool ok = writeAll(pbase(), size_t(pptr() - pbase()));
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return ok;
    }
    bool writeAll(const char* data, size_t count) {
        while (error_ == 0 && count > 0) {
            const ssize_t written = ::write(fd_, data, count);
            if (written < 0 && errno == EINTR) continue;
            if (written < 0) error_ = errno;
            else data += written, count -= size_t(written);
        }
        return error_ == 0;
    }

    int fd_;
    int error_ = 0;
    std::array<char, 1 << 16> buffer_;
};

// Writes, keeps a replaced file's permissions, syncs and closes `fd`; returns an errno or 0.
int writeAndSync(int fd, const fs::path& target, const std::function<void(std::ostream&)>& write) {
    int error = 0;
    try {
        FdBuffer buffer(fd);
        std::ostream out(&buffer);
        write(out);
        out.flush();
        error = buffer.error();
        if (error == 0 && !out) error = EIO;
    } catch (...) {
        ::close(fd);
        throw;
    }
    struct stat previous {};
    if (error == 0 && ::stat(target.c_str(), &previous) == 0 && ::fchmod(fd, previous.st_mode & 07777) != 0) error = errno;
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    return error;
}

} // namespace

struct OutputFiles::Staged {
    std::string shownPath; // as the user gave it, for messages
    fs::path target;       // the file replaced: the path, or a symlink's target
    fs::path temp;
    bool tempExists = false;
    CleanupEntry tempEntry;
    // While several files are committed: a hard link to (or copy of) target's previous file ...
    fs::path backup;
    CleanupEntry backupEntry;
    // ... or, when there was none, the entry that removes the new file on a signal.
    CleanupEntry createdEntry;
};

OutputFiles::OutputFiles() = default;

OutputFiles::~OutputFiles() { discard(); }

void OutputFiles::discard() noexcept {
    for (const std::unique_ptr<Staged>& staged : staged_) {
        if (staged->tempExists) ::unlink(staged->temp.c_str());
        if (!staged->backup.empty()) ::unlink(staged->backup.c_str());
    }
    staged_.clear(); // releases the registry entries
}

void OutputFiles::add(const std::string& path, const std::function<void(std::ostream&)>& write) {
    VOXC_ASSERT(!committed_);
    if (staged_.size() == kMaxFiles)
        throw cannotWrite(path, fmt::format("more than {} files in one set of outputs", kMaxFiles));
    auto staged = std::make_unique<Staged>();
    staged->shownPath = path;
    staged->target = resolveTarget(path);
    // Renaming over a device or a pipe (say a link to /dev/null) would replace it with a file.
    std::error_code unknown; // then open() below says why
    const fs::file_status status = fs::status(staged->target, unknown);
    if (fs::is_directory(status)) throw cannotWrite(path, "it is a directory");
    if (fs::exists(status) && !fs::is_regular_file(status)) throw cannotWrite(path, "it is not a regular file");

    int fd = -1;
    for (int attempt = 0; fd < 0; ++attempt) {
        if (attempt == 100) throw cannotWrite(path, "every temp file name beside it is taken");
        staged->temp = siblingName(staged->target);
        staged->tempEntry = CleanupEntry(staged->temp.string());
        // Armed before open() creates the file, so a signal between the two cannot leave it
        // behind; a name an earlier process left is skipped without arming it.
        if (::access(staged->temp.c_str(), F_OK) == 0) continue;
        staged->tempEntry.removeOnSignal();
        fd = ::open(staged->temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) {
            const int openError = errno;
            staged->tempEntry.ignoreOnSignal();
            if (openError != EEXIST) throw cannotWrite(path, std::strerror(openError));
        }
    }
    staged->tempExists = true;
    int error = 0;
    try {
        error = writeAndSync(fd, staged->target, write);
    } catch (...) {
        ::unlink(staged->temp.c_str());
        throw;
    }
    if (error != 0) {
        ::unlink(staged->temp.c_str());
        throw cannotWrite(path, std::strerror(error));
    }
    staged_.push_back(std::move(staged));
}

void OutputFiles::add(const std::string& path, std::string_view contents) {
    add(path, [&](std::ostream& out) { out.write(contents.data(), std::streamsize(contents.size())); });
}

void OutputFiles::commit() {
    VOXC_ASSERT(!committed_);
    committed_ = true;
    try {
        renameAll();
    } catch (...) {
        discard();
        throw;
    }
    discard(); // only the entries are left
}

void OutputFiles::renameAll() {
    // One file is replaced by one rename, which happens or not. With several, every file that is
    // replaced keeps a backup until all renames are done, so a failure can put them all back.
    const bool several = staged_.size() > 1;
    for (const std::unique_ptr<Staged>& staged : staged_) {
        struct stat previous {};
        if (!several || ::lstat(staged->target.c_str(), &previous) != 0) continue; // nothing to keep
        std::string backup = siblingName(staged->target);
        CleanupEntry entry(backup);
        entry.removeOnSignal(); // before the link exists, so a signal cannot leave it behind
        if (::link(staged->target.c_str(), backup.c_str()) != 0) {
            // A file system without hard links: a copy does as well.
            std::error_code ec;
            if (!fs::copy_file(staged->target, backup, ec))
                throw cannotWrite(staged->shownPath, fmt::format("cannot keep a copy of the previous file: {}", ec.message()));
        }
        staged->backup = backup;
        staged->backupEntry = std::move(entry);
    }
    for (size_t i = 0; i < staged_.size(); ++i) {
        Staged& file = *staged_[i];
        if (several && !file.backup.empty()) file.backupEntry.restoreOnSignal(file.target.string());
        if (several && file.backup.empty()) {
            file.createdEntry = CleanupEntry(file.target.string());
            file.createdEntry.removeOnSignal();
        }
        if (::rename(file.temp.c_str(), file.target.c_str()) != 0) {
            std::string why = std::strerror(errno);
            for (size_t done = 0; done < i; ++done) {
                Staged& renamed = *staged_[done];
                if (renamed.backup.empty()) {
                    ::unlink(renamed.target.c_str());
                    continue;
                }
                // A backup that cannot be put back stays, and the message says where.
                if (::rename(renamed.backup.c_str(), renamed.target.c_str()) != 0)
                    why += fmt::format("; the previous '{}' is kept as '{}'", renamed.shownPath, renamed.backup.string());
                renamed.backupEntry.ignoreOnSignal();
                renamed.backup.clear();
            }
            throw cannotWrite(file.shownPath, why);
        }
        file.tempExists = false;
        file.tempEntry.ignoreOnSignal();
    }
    // Done: from now on a signal removes the backups rather than putting them back.
    for (const std::unique_ptr<Staged>& staged : staged_) {
        staged->createdEntry = CleanupEntry();
        if (!staged->backup.empty()) staged->backupEntry.removeOnSignal();
    }
}

OutputDirectory::OutputDirectory(const std::string& path) {
    const auto refuse = [&](const std::string& why) {
        return UserError(fmt::format("cannot write into '{}': {}", path, why));
    };
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(path, ec);
    const fs::file_status status = fs::status(path, ec);
    if (fs::is_symlink(link) && !fs::exists(status))
        throw refuse(fmt::format("it is a link to '{}', which does not exist", fs::read_symlink(path, ec).string()));
    if (fs::exists(status) && !fs::is_directory(status)) throw refuse("it exists and is not a directory");
    if (!fs::exists(status)) {
        // The missing directories, innermost first, up to the first that exists.
        std::vector<fs::path> missing;
        for (fs::path at = fs::absolute(path, ec).lexically_normal(); !at.empty(); at = at.parent_path()) {
            if (fs::exists(fs::symlink_status(at, ec)) || at == at.parent_path()) break;
            missing.push_back(at);
        }
        for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
            if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST) {
                const std::string why = std::strerror(errno);
                for (auto made = created_.rbegin(); made != created_.rend(); ++made) ::rmdir(made->c_str());
                created_.clear();
                throw refuse(fmt::format("cannot create '{}': {}", it->string(), why));
            }
            created_.push_back(*it);
        }
    }
    if (::access(path.c_str(), R_OK | W_OK | X_OK) != 0) {
        const std::string why = std::strerror(errno);
        for (auto made = created_.rbegin(); made != created_.rend(); ++made) ::rmdir(made->c_str());
        created_.clear();
        throw refuse(why);
    }
}

OutputDirectory::~OutputDirectory() {
    // rmdir removes only an empty directory: whatever was written into one keeps it.
    for (auto made = created_.rbegin(); made != created_.rend(); ++made)
        if (::rmdir(made->c_str()) != 0) break;
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    OutputFiles files;
    files.add(path, write);
    files.commit();
}

void writeFileAtomically(const std::string& path, std::string_view contents) {
    OutputFiles files;
    files.add(path, contents);
    files.commit();
}

} // namespace voxc

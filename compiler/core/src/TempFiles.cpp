#include "voxc/core/TempFiles.h"

#include "voxc/core/Errors.h"

#include <array>
#include <atomic>
#include <climits>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <mutex>
#include <unistd.h>

namespace voxc {

namespace {

enum SlotState : int { kFree, kIgnore, kRemove, kRestore, kRemoveTree };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
    char target[PATH_MAX]; // read only in kRestore
};

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads slot states without locks");

constexpr int kSlots = kCleanupSlots;
// Subdirectory levels below a kRemoveTree directory that the handler removes (a package has one).
constexpr int kMaxTreeDepth = 4;
std::array<Slot, kSlots> slots;

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Removes the directory `name` (relative to `parentFd`) and everything in it, at most `depth`
// levels of subdirectories, with async-signal-safe calls only (openat, getdents64, unlinkat,
// lseek, close) and no allocation. Each pass rereads the directory from its start, because
// entries unlinked while it is being read may make the read skip others.
void removeTree(int parentFd, const char* name, int depth) {
    const int fd = ::openat(parentFd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return;
    alignas(dirent64) char buffer[2048];
    for (bool removed = true; removed;) {
        removed = false;
        ::lseek(fd, 0, SEEK_SET);
        for (ssize_t n; (n = ::getdents64(fd, buffer, sizeof buffer)) > 0;) {
            for (ssize_t at = 0; at < n;) {
                const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
                at += entry->d_reclen;
                const char* child = entry->d_name;
                if (child[0] == '.' && (child[1] == 0 || (child[1] == '.' && child[2] == 0))) continue;
                if (::unlinkat(fd, child, 0) == 0) {
                    removed = true;
                } else if (errno == EISDIR && depth > 0) {
                    removeTree(fd, child, depth - 1);
                    removed = true;
                }
            }
        }
    }
    ::close(fd);
    ::unlinkat(parentFd, name, AT_REMOVEDIR);
}

extern "C" void cleanUpAndDie(int signal) {
    for (Slot& slot : slots) {
        switch (slot.state.load(std::memory_order_acquire)) {
        case kRemove: ::unlink(slot.path); break;
        case kRemoveTree: removeTree(AT_FDCWD, slot.path, kMaxTreeDepth); break;
        case kRestore:
            ::rename(slot.path, slot.target);
            ::unlink(slot.path);
            break;
        default: break;
        }
    }
    // SA_RESETHAND put back the default action; the signal stays blocked until this handler
    // returns and then kills the process.
    ::raise(signal);
}

void copyPath(char (&into)[PATH_MAX], const std::string& path) {
    if (path.size() >= PATH_MAX) throw UserError(fmt::format("cannot write '{}': the path is too long", path));
    std::memcpy(into, path.c_str(), path.size() + 1);
}

} // namespace

void installTempFileCleanup() {
    static std::once_flag installed;
    std::call_once(installed, [] {
        for (int signal : kCleanupSignals) {
            struct sigaction previous {};
            if (::sigaction(signal, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN) continue;
            struct sigaction action {};
            action.sa_handler = cleanUpAndDie;
            action.sa_flags = SA_RESETHAND;
            sigemptyset(&action.sa_mask);
            for (int other : kCleanupSignals) sigaddset(&action.sa_mask, other);
            ::sigaction(signal, &action, nullptr);
        }
    });
}

CleanupEntry::CleanupEntry(const std::string& path) {
    const std::string absolute = std::filesystem::absolute(path).string();
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slots[size_t(i)].state.compare_exchange_strong(expected, kIgnore)) continue;
        slot_ = i;
        try {
            copyPath(slots[size_t(i)].path, absolute);
        } catch (...) {
            slots[size_t(i)].state.store(kFree);
            slot_ = -1;
            throw;
        }
        return;
    }
    throw InternalError(fmt::format("more than {} files in flight while writing '{}'", kSlots, path));
}

CleanupEntry::CleanupEntry(CleanupEntry&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }

CleanupEntry& CleanupEntry::operator=(CleanupEntry&& other) noexcept {
    if (this != &other) {
        if (slot_ >= 0) slots[size_t(slot_)].state.store(kFree, std::memory_order_release);
        slot_ = other.slot_;
        other.slot_ = -1;
    }
    return *this;
}

CleanupEntry::~CleanupEntry() {
    if (slot_ >= 0) slots[size_t(slot_)].state.store(kFree, std::memory_order_release);
}

void CleanupEntry::removeOnSignal() {
    VOXC_ASSERT(slot_ >= 0);
    slots[size_t(slot_)].state.store(kRemove, std::memory_order_release);
}

void CleanupEntry::restoreOnSignal(const std::string& target) {
    VOXC_ASSERT(slot_ >= 0);
    Slot& slot = slots[size_t(slot_)];
    // The handler reads `target` only in kRestore, so it is written before the state says so.
    VOXC_ASSERT(slot.state.load() != kRestore);
    copyPath(slot.target, std::filesystem::absolute(target).string());
    slot.state.store(kRestore, std::memory_order_release);
}

void CleanupEntry::removeTreeOnSignal() {
    VOXC_ASSERT(slot_ >= 0);
    slots[size_t(slot_)].state.store(kRemoveTree, std::memory_order_release);
}

void CleanupEntry::ignoreOnSignal() {
    VOXC_ASSERT(slot_ >= 0);
    slots[size_t(slot_)].state.store(kIgnore, std::memory_order_release);
}

int cleanupEntriesInUse() {
    int used = 0;
    for (const Slot& slot : slots) used += slot.state.load() != kFree;
    return used;
}

} // namespace voxc

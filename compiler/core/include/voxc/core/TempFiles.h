#pragma once
// Files voxc is in the middle of writing, known to a signal handler: on SIGINT, SIGTERM or SIGHUP
// it removes every temp file, puts back every file a half-done commit replaced, and then dies of
// the signal exactly as without a handler (the shell sees "killed by SIGINT").
//
// The registry is a fixed array of slots with inline paths, so the handler only reads memory
// that is never freed and calls only unlink() and rename() (both async-signal-safe).
#include <string>

namespace voxc {

// Registry slots: the most temp files, backups and new files voxc has in flight at once. A set of
// N output files holds at most 2N (OutputFiles::kMaxFiles is half of this).
constexpr int kCleanupSlots = 512;

// Installs the handler for SIGINT, SIGTERM and SIGHUP, except for a signal that is ignored when
// voxc starts (under `nohup`, or a background job of a non-interactive shell): ignored stays
// ignored. Idempotent. The voxc executable calls it before doing anything.
void installTempFileCleanup();

// One registry slot, owned by one object and released by its destructor. A new entry does nothing
// on a signal until told what to do, so that a file can be registered before it exists and the
// handler never touches a name that belongs to someone else.
class CleanupEntry {
public:
    CleanupEntry() = default;
    // Claims a slot for `path` (made absolute). UserError if the path does not fit a slot;
    // InternalError if every slot is taken (more files in flight than voxc ever writes at once).
    explicit CleanupEntry(const std::string& path);
    CleanupEntry(CleanupEntry&& other) noexcept;
    CleanupEntry& operator=(CleanupEntry&& other) noexcept;
    CleanupEntry(const CleanupEntry&) = delete;
    CleanupEntry& operator=(const CleanupEntry&) = delete;
    ~CleanupEntry();

    // On a signal: unlink the path.
    void removeOnSignal();
    // On a signal: rename the path (a backup) over `target`, then unlink the path (in case both
    // were links to one file, where rename does nothing).
    void restoreOnSignal(const std::string& target);
    // On a signal: remove the path, a temp directory, and everything in it (up to four levels of
    // subdirectories; `voxc compile` builds its package in one).
    void removeTreeOnSignal();
    // On a signal: nothing.
    void ignoreOnSignal();

private:
    int slot_ = -1;
};

// How many slots are in use (for tests: every entry must be released after a write).
int cleanupEntriesInUse();

} // namespace voxc

#pragma once
// Every output file is written to a temp file beside it and renamed into place, so readers see
// the old file or the new one, never a partial one, and a failure or a signal (TempFiles.h) leaves
// the user's files as they were. The outputs of one command are committed together.
#include "voxc/core/TempFiles.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace voxc {

// A set of files written all or nothing. add() writes a file's new contents to a temp file in
// the same directory ("PATH.tmp-PID-N", created exclusively, so concurrent processes and threads
// never share one); nothing of the user's changes until commit(). A path that is a symlink is
// written through: its target is replaced and the link stays.
class OutputFiles {
public:
    // The most files one set holds (each has a temp file and, while committing, a backup).
    static constexpr size_t kMaxFiles = size_t(kCleanupSlots) / 2;

    OutputFiles();
    ~OutputFiles(); // removes the temp files of a set that was not committed
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Throws UserError ("cannot write 'PATH': why") if the temp file cannot be written, if
    // PATH is a directory, a device or a pipe, or if the set already holds kMaxFiles files; the
    // temp file is gone again then.
    void add(const std::string& path, const std::function<void(std::ostream&)>& write);
    void add(const std::string& path, std::string_view contents);

    // Renames every temp file over its path, in the order added. If a rename fails, the files
    // already renamed get their previous contents back (or are removed, if this set created
    // them) and UserError is thrown; a signal meanwhile does the same (TempFiles.h).
    void commit();

private:
    struct Staged;
    void renameAll();
    void discard() noexcept; // removes what is left of the temp files and backups
    std::vector<std::unique_ptr<Staged>> staged_;
    bool committed_ = false;
};

// An output directory (`voxc evolve -o`, `voxc world -o`), made ready before any work: created,
// with its missing parents, when it does not exist. UserError ("cannot write into 'PATH': why")
// when the path names a file or a dangling link, or when a directory cannot be created or
// written in. The directories it created are removed again when it is destroyed, if still
// empty, unless keep() was called: a command that fails leaves no empty folder behind, and never
// removes one it did not make.
class OutputDirectory {
public:
    explicit OutputDirectory(const std::string& path);
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory&) = delete;
    OutputDirectory& operator=(const OutputDirectory&) = delete;

    // The command succeeded (or wrote something worth keeping): the directories stay.
    void keep() { created_.clear(); }

private:
    std::vector<std::filesystem::path> created_; // outermost first
};

// One file on its own: an OutputFiles of one, committed at once.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);
void writeFileAtomically(const std::string& path, std::string_view contents);

} // namespace voxc

#pragma once
// Every output file is written to a temp file beside it and renamed into place, so readers see
// the old file or the new one, never a partial one, and a failure or a signal (TempFiles.h) leaves
// the user's files as they were. The outputs of one command are committed together.
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
    OutputFiles();
    ~OutputFiles(); // removes the temp files of a set that was not committed
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Throws UserError ("cannot write 'PATH': why") if the temp file cannot be written, or if
    // PATH is a directory, a device or a pipe; the temp file is gone again then.
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

// One file on its own: an OutputFiles of one, committed at once.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);
void writeFileAtomically(const std::string& path, std::string_view contents);

} // namespace voxc

#pragma once
// Reading a file that a .vox file names (an lsystem's `rules = "..."`, a heightmap or mesh
// input's `file = "..."`): the name comes from the text being checked, so it may be anything the
// path reaches. Only a regular file is read, and never more than a cap: a FIFO would block the
// check forever, and /dev/stdin or a terminal is the process's own input (for `voxc lsp`, the
// protocol stream the editor speaks on). The check is made before anything is read, on the file
// opened with O_NONBLOCK so that opening a FIFO without a writer returns at once.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace voxc {

// What stopped a read; None when the bytes were read.
enum class InputFileProblem {
    None,
    Missing,    // no such file (or a component of the path is not a directory)
    NotRegular, // a directory, FIFO, socket or device: refused before reading
    TooLarge,   // over the cap: refused from its size, or when more than the cap could be read
    Unreadable, // permission denied, an I/O error, ...
};

struct InputFileRead {
    std::optional<std::string> bytes; // the whole file, at most the cap; set when problem is None
    InputFileProblem problem = InputFileProblem::None;
    std::string message; // when problem is not None: "cannot read file 'PATH': why", one line

    // The diagnostic code a checker reports the problem with: E0012 for TooLarge (a limit the
    // user can read in docs/language.md), E0100 otherwise.
    std::string_view code() const { return problem == InputFileProblem::TooLarge ? "E0012" : "E0100"; }
};

// Reads the regular file `path`, never more than `maxBytes` bytes (and never blocking on what
// the path names). Never throws for a problem of the file; see InputFileRead.
InputFileRead readInputFile(const std::string& path, uint64_t maxBytes);

// The same read for a path given on the command line (`voxc check FILE`, `--edits FILE`): the
// user chose it, so a pipe or device (`voxc check /dev/stdin < x.vox`) is read as well, up to one
// byte past the cap; a directory is still refused.
InputFileRead readCommandLineFile(const std::string& path, uint64_t maxBytes);

} // namespace voxc

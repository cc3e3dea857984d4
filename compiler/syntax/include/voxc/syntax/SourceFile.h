#pragma once
// A .vox file's text and path, with a line index for rendering diagnostics. Loading never
// throws for the user's mistakes: a missing or binary file becomes a diagnostic.
#include "voxc/syntax/Diagnostics.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc {

class SourceFile {
public:
    SourceFile() = default;
    SourceFile(std::string path, std::string text);

    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }
    // Line `line` (1-based) without its line terminator; empty when out of range.
    std::string_view line(uint32_t line) const;
    uint32_t lineCount() const { return uint32_t(lineStarts_.size()); }

private:
    std::string path_;
    std::string text_;
    std::vector<size_t> lineStarts_;
};

// The default cap on a source file's size (Limits::maxSourceBytes): 4 MiB. Parsing costs about
// 150 bytes of memory per source byte (ANTLR's tokens and tree), so this bounds a check to
// roughly 600 MB.
constexpr size_t kDefaultMaxSourceBytes = size_t(4) << 20;

// Reads `path`, a file given on the command line, with readCommandLineFile (voxc/core/InputFile.h):
// never more than `maxBytes + 1` bytes, a pipe or device included. On failure reports E0100
// (E0012 when the file, pipe or device holds more than `maxBytes`) and returns nothing. The text
// is not validated; see reportIfNotText. A file a .vox names is read with readInputFile instead.
std::optional<SourceFile> loadSourceFile(const std::string& path, Diagnostics& diagnostics,
                                         size_t maxBytes = kDefaultMaxSourceBytes);

// Reports E0101 (and returns true) when the text holds a NUL byte or is not valid UTF-8, located
// at the first such byte (line, and column in characters).
bool reportIfNotText(const SourceFile& source, Diagnostics& diagnostics);

// Whether `text` holds no NUL byte and is valid UTF-8 (a line the diagnostics may print).
bool isText(std::string_view text);

} // namespace voxc

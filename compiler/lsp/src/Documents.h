#pragma once
// The documents the editor has open, and the position arithmetic between the checker's
// locations (1-based line, column in characters) and LSP's (0-based line, UTF-16 code units).
#include "voxc/core/SourceLoc.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace voxc::lsp {

struct Position {
    uint32_t line = 0;      // 0-based
    uint32_t character = 0; // UTF-16 code units from the line's start
};

// "file:///a/b%20c.vox" -> "/a/b c.vox"; another scheme is returned unchanged.
std::string uriToPath(std::string_view uri);
std::string pathToUri(std::string_view path);

// Line `line` (0-based) of `text` without its terminator; empty past the end.
std::string_view lineOf(std::string_view text, uint32_t line);

// UTF-16 units before character `column` (0-based, in code points) of `line`, and the reverse.
uint32_t utf16Offset(std::string_view line, uint32_t column);
uint32_t characterColumn(std::string_view line, uint32_t utf16);

// The checker's 1-based location on `line`'s text as LSP start and end positions.
Position startOf(SourceLoc loc, std::string_view lineText);
Position endOf(SourceLoc loc, std::string_view lineText);

// Byte offset of an LSP position in `text` (clamped to the line's end and the text's end).
size_t byteOffset(std::string_view text, Position position);

} // namespace voxc::lsp

#include "Documents.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::lsp {

namespace {

bool isContinuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// UTF-16 units of the code point starting with lead byte `c`: 2 beyond the basic plane.
uint32_t utf16Units(char c) { return static_cast<unsigned char>(c) >= 0xF0 ? 2 : 1; }

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Where a walk over a line's UTF-8 characters stopped: LSP counts UTF-16 units, the checker characters.
struct LineCursor {
    size_t byte = 0;
    uint32_t characters = 0;
    uint32_t units = 0;
};

template <typename Done> LineCursor walkLine(std::string_view line, Done done) {
    LineCursor cursor;
    while (cursor.byte < line.size() && !done(cursor)) {
        cursor.units += utf16Units(line[cursor.byte]);
        ++cursor.characters;
        ++cursor.byte;
        while (cursor.byte < line.size() && isContinuation(line[cursor.byte])) ++cursor.byte;
    }
    return cursor;
}

} // namespace

std::string uriToPath(std::string_view uri) {
    constexpr std::string_view kScheme = "file://";
    if (!uri.starts_with(kScheme)) return std::string(uri);
    uri.remove_prefix(kScheme.size());
    std::string path;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
            path.push_back(char(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2])));
            i += 2;
        } else {
            path.push_back(uri[i]);
        }
    }
    return path;
}

std::string pathToUri(std::string_view path) {
    if (!path.starts_with('/')) return std::string(path);
    std::string uri = "file://";
    for (const char c : path) {
        const bool unreserved = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                                c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
        uri += unreserved ? std::string(1, c) : fmt::format("%{:02X}", static_cast<unsigned char>(c));
    }
    return uri;
}

std::string_view lineOf(std::string_view text, uint32_t line) {
    size_t start = 0;
    for (uint32_t l = 0; l < line; ++l) {
        const size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) return {};
        start = newline + 1;
    }
    std::string_view rest = text.substr(start);
    rest = rest.substr(0, rest.find('\n'));
    if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
    return rest;
}

uint32_t utf16Offset(std::string_view line, uint32_t column) {
    const LineCursor cursor = walkLine(line, [&](const LineCursor& c) { return c.characters >= column; });
    return cursor.units + (column - cursor.characters); // columns past the end count one unit each
}

uint32_t characterColumn(std::string_view line, uint32_t utf16) {
    return walkLine(line, [&](const LineCursor& c) { return c.units >= utf16; }).characters;
}

Position startOf(SourceLoc loc, std::string_view lineText) {
    if (loc.line == 0) return {};
    return {loc.line - 1, utf16Offset(lineText, loc.column == 0 ? 0 : loc.column - 1)};
}

Position endOf(SourceLoc loc, std::string_view lineText) {
    if (loc.line == 0) return {};
    return {loc.line - 1, utf16Offset(lineText, (loc.column == 0 ? 0 : loc.column - 1) + std::max<uint32_t>(loc.length, 1))};
}

size_t byteOffset(std::string_view text, Position position) {
    size_t start = 0;
    for (uint32_t l = 0; l < position.line; ++l) {
        const size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) return text.size();
        start = newline + 1;
    }
    const std::string_view line = lineOf(text.substr(start), 0);
    return start + walkLine(line, [&](const LineCursor& c) { return c.units >= position.character; }).byte;
}

} // namespace voxc::lsp

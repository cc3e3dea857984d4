#include "voxc/syntax/SourceFile.h"

#include "voxc/core/InputFile.h"

#include <fmt/format.h>


namespace voxc {

SourceFile::SourceFile(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
    lineStarts_.push_back(0);
    for (size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n' && i + 1 < text_.size()) lineStarts_.push_back(i + 1);
}

std::string_view SourceFile::line(uint32_t line) const {
    if (line == 0 || line > lineStarts_.size()) return {};
    size_t begin = lineStarts_[line - 1];
    size_t end = text_.find('\n', begin);
    if (end == std::string::npos) end = text_.size();
    if (end > begin && text_[end - 1] == '\r') --end;
    return std::string_view(text_).substr(begin, end - begin);
}

std::optional<SourceFile> loadSourceFile(const std::string& path, Diagnostics& diagnostics, size_t maxBytes) {
    InputFileRead read = readCommandLineFile(path, maxBytes);
    if (read.bytes) return SourceFile(path, std::move(*read.bytes));
    diagnostics.error(std::string(read.code()), {}, read.message);
    return std::nullopt;
}

namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is malformed
// (bad lead byte, bad continuation, overlong form, surrogate or beyond U+10FFFF).
size_t utf8SequenceLength(std::string_view text, size_t i) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    unsigned char lead = byte(i);
    if (lead < 0x80) return 1;
    size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
    if (length == 0 || lead > 0xF4 || i + length > text.size()) return 0;
    uint32_t cp = lead & (0x7F >> length);
    for (size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    bool overlong = (length == 3 && cp < 0x800) || (length == 4 && cp < 0x10000);
    bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
    return overlong || surrogate || cp > 0x10FFFF ? 0 : length;
}

} // namespace

bool isText(std::string_view text) {
    for (size_t i = 0; i < text.size();) {
        const size_t length = utf8SequenceLength(text, i);
        if (text[i] == '\0' || length == 0) return false;
        i += length;
    }
    return true;
}

bool reportIfNotText(const SourceFile& source, Diagnostics& diagnostics) {
    std::string_view text = source.text();
    uint32_t line = 1;
    uint32_t column = 1;
    for (size_t i = 0; i < text.size();) {
        size_t length = utf8SequenceLength(text, i);
        std::string_view what = text[i] == '\0' ? "a NUL byte" : length == 0 ? "invalid UTF-8" : "";
        if (!what.empty()) {
            diagnostics.error("E0101", {line, column, 1}, fmt::format("not a text file: {}", what));
            return true;
        }
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        i += length;
    }
    return false;
}

} // namespace voxc

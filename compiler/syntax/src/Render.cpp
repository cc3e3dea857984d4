#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace voxc {

const char* severityName(Severity severity) {
    switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    }
    return "error";
}

namespace {

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Lines longer than this many characters are shown as a window around the caret, so that a
// file of one 4 MB line does not print 4 MB per diagnostic.
constexpr size_t kMaxShownCharacters = 160;
constexpr size_t kShownBeforeCaret = 60;

// The source line and a caret line under columns [column, column + length) (in characters),
// clipped to the line. Tabs before the caret are kept so the caret lines up in a terminal.
std::string snippet(const SourceFile& source, SourceLoc loc, const std::vector<FixIt>& fixits) {
    std::string_view text = source.line(loc.line);
    std::vector<size_t> starts; // byte offset of each character
    for (size_t i = 0; i < text.size(); ++i)
        if (!isContinuationByte(text[i])) starts.push_back(i);
    const size_t caret = std::min<size_t>(loc.column == 0 ? 0 : loc.column - 1, starts.size());
    size_t first = 0, last = starts.size(); // shown characters [first, last)
    if (starts.size() > kMaxShownCharacters) {
        const size_t lastFirst = starts.size() - kMaxShownCharacters;
        first = caret > kShownBeforeCaret ? std::min(caret - kShownBeforeCaret, lastFirst) : 0;
        last = first + kMaxShownCharacters;
    }
    auto byteAt = [&](size_t character) { return character < starts.size() ? starts[character] : text.size(); };
    const std::string before = first > 0 ? "..." : "";
    const std::string after = last < starts.size() ? "..." : "";
    // Blanks up to character `column` (clipped to the shown window), tabs kept.
    auto marginTo = [&](size_t column) {
        std::string margin(before.size(), ' ');
        for (size_t c = first; c < std::min(column, starts.size()); ++c) margin += text[starts[c]] == '\t' ? '\t' : ' ';
        return margin;
    };
    const size_t remaining = last > caret ? last - caret : 0;
    const size_t width = std::max<size_t>(1, std::min<size_t>(loc.length, remaining));
    std::string gutter = fmt::format("{:>5} | ", loc.line);
    const std::string_view shown = text.substr(byteAt(first), byteAt(last) - byteAt(first));
    std::string out = fmt::format("{}{}{}{}\n      | {}^{}\n", gutter, before, shown, after, marginTo(caret),
                                  std::string(width - 1, '~'));
    // clang's fix-it line: the replacement under the text it replaces, when that text is shown.
    for (const FixIt& fixit : fixits) {
        const size_t column = fixit.loc.column == 0 ? 0 : fixit.loc.column - 1;
        if (fixit.loc.line != loc.line || column < first || column > last) continue;
        out += fmt::format("      | {}{}\n", marginTo(column), fixit.replacement);
    }
    return out;
}

void renderOne(std::string& out, Severity severity, std::string_view code, SourceLoc loc, std::string_view message,
               const SourceFile& source, const std::vector<FixIt>& fixits = {}) {
    std::string label = code.empty() ? severityName(severity) : fmt::format("{} {}", severityName(severity), code);
    if (loc.line == 0) {
        out += fmt::format("{}: {}: {}\n", source.path(), label, message);
        return;
    }
    out += fmt::format("{}:{}:{}: {}: {}\n", source.path(), loc.line, loc.column, label, message);
    // A line that is not text (E0101's) is not printed: its bytes would garble the terminal.
    if (loc.line <= source.lineCount() && !source.text().empty() && isText(source.line(loc.line)))
        out += snippet(source, loc, fixits);
}

} // namespace

std::string render(const Diagnostic& diagnostic, const SourceFile& checked) {
    const SourceFile& source = diagnostic.file ? *diagnostic.file : checked;
    std::string out;
    renderOne(out, diagnostic.severity, diagnostic.code, diagnostic.loc, diagnostic.message, source, diagnostic.fixits);
    for (const DiagnosticNote& note : diagnostic.notes)
        renderOne(out, Severity::Note, "", note.loc, note.message, source);
    return out;
}

std::string renderAll(const std::vector<Diagnostic>& diagnostics, const SourceFile& source) {
    std::string out;
    for (const Diagnostic& diagnostic : diagnostics) out += render(diagnostic, source);
    return out;
}

} // namespace voxc

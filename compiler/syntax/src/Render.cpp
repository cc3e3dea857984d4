#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <fmt/format.h>

namespace voxc {

namespace {

const char* severityName(Severity severity) {
    switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    }
    return "error";
}

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The source line and a caret line under columns [column, column + length) (in characters),
// clipped to the line. Tabs before the caret are kept so the caret lines up in a terminal.
std::string snippet(const SourceFile& source, SourceLoc loc) {
    std::string_view text = source.line(loc.line);
    std::string margin;
    uint32_t column = 1;
    size_t i = 0;
    for (; i < text.size() && column < loc.column; ++i) {
        if (isContinuationByte(text[i])) continue;
        margin += text[i] == '\t' ? '\t' : ' ';
        ++column;
    }
    uint32_t remaining = 0;
    for (size_t k = i; k < text.size(); ++k)
        if (!isContinuationByte(text[k])) ++remaining;
    uint32_t width = std::max<uint32_t>(1, std::min(loc.length, remaining));
    std::string gutter = fmt::format("{:>5} | ", loc.line);
    return fmt::format("{}{}\n      | {}^{}\n", gutter, text, margin, std::string(width - 1, '~'));
}

void renderOne(std::string& out, Severity severity, std::string_view code, SourceLoc loc, std::string_view message,
               const SourceFile& source) {
    std::string label = code.empty() ? severityName(severity) : fmt::format("{} {}", severityName(severity), code);
    if (loc.line == 0) {
        out += fmt::format("{}: {}: {}\n", source.path(), label, message);
        return;
    }
    out += fmt::format("{}:{}:{}: {}: {}\n", source.path(), loc.line, loc.column, label, message);
    if (loc.line <= source.lineCount() && !source.text().empty()) out += snippet(source, loc);
}

} // namespace

std::string render(const Diagnostic& diagnostic, const SourceFile& source) {
    std::string out;
    renderOne(out, diagnostic.severity, diagnostic.code, diagnostic.loc, diagnostic.message, source);
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

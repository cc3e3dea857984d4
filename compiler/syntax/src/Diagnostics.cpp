#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <algorithm>
#include <tuple>
#include <fmt/format.h>

namespace voxc {

namespace {

// Everything that makes two diagnostics the same, as one string, so that duplicates are found
// in a set rather than by comparing with every diagnostic so far (100000 warnings took 36 s).
std::string identity(const Diagnostic& d) {
    std::string key = fmt::format("{}\x1f{}\x1f{}\x1f{}:{}:{}\x1f{}", int(d.severity), d.code,
                                  d.file ? d.file->path() : std::string(), d.loc.line, d.loc.column, d.loc.length,
                                  d.message);
    for (const DiagnosticNote& note : d.notes)
        key += fmt::format("\x1e{}:{}:{}\x1f{}", note.loc.line, note.loc.column, note.loc.length, note.message);
    return key;
}

} // namespace

void Diagnostics::report(Diagnostic diagnostic) {
    if (truncated_ && diagnostic.severity == Severity::Error) return;
    if (!seen_.insert(identity(diagnostic)).second) return;
    if (diagnostic.severity == Severity::Error && errorCount_ == kMaxErrors) {
        truncated_ = true;
        diagnostics_.push_back({Severity::Error, "", {},
                                fmt::format("too many errors; stopping after the first {}", kMaxErrors), {}, nullptr});
        return;
    }
    if (diagnostic.severity == Severity::Error) ++errorCount_;
    diagnostics_.push_back(std::move(diagnostic));
}

void Diagnostics::error(std::string_view code, SourceLoc loc, std::string message, std::vector<DiagnosticNote> notes) {
    report({Severity::Error, std::string(code), loc, std::move(message), std::move(notes), nullptr});
}

void Diagnostics::warning(std::string_view code, SourceLoc loc, std::string message,
                          std::vector<DiagnosticNote> notes) {
    report({Severity::Warning, std::string(code), loc, std::move(message), std::move(notes), nullptr});
}

std::vector<Diagnostic> Diagnostics::take() {
    // The cap line has neither a code nor a location; it stays last.
    auto key = [](const Diagnostic& d) {
        const bool capLine = d.code.empty() && d.loc.line == 0;
        return std::make_tuple(capLine, d.file ? d.file->path() : std::string(), d.loc.line, d.loc.column);
    };
    std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
    return std::move(diagnostics_);
}

} // namespace voxc

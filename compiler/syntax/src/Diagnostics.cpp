#include "voxc/syntax/Diagnostics.h"

#include <algorithm>
#include <tuple>
#include <fmt/format.h>

namespace voxc {

namespace {

bool sameLoc(const SourceLoc& a, const SourceLoc& b) {
    return a.line == b.line && a.column == b.column && a.length == b.length;
}

bool sameNotes(const std::vector<DiagnosticNote>& a, const std::vector<DiagnosticNote>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const DiagnosticNote& x, const DiagnosticNote& y) {
        return sameLoc(x.loc, y.loc) && x.message == y.message;
    });
}

bool sameDiagnostic(const Diagnostic& a, const Diagnostic& b) {
    return a.severity == b.severity && a.code == b.code && sameLoc(a.loc, b.loc) && a.message == b.message &&
           sameNotes(a.notes, b.notes);
}

} // namespace

void Diagnostics::report(Diagnostic diagnostic) {
    if (truncated_ && diagnostic.severity == Severity::Error) return;
    if (std::any_of(diagnostics_.begin(), diagnostics_.end(),
                    [&](const Diagnostic& seen) { return sameDiagnostic(seen, diagnostic); }))
        return;
    if (diagnostic.severity == Severity::Error && errorCount_ == kMaxErrors) {
        truncated_ = true;
        diagnostics_.push_back({Severity::Error, "", {},
                                fmt::format("too many errors; stopping after the first {}", kMaxErrors), {}});
        return;
    }
    if (diagnostic.severity == Severity::Error) ++errorCount_;
    diagnostics_.push_back(std::move(diagnostic));
}

void Diagnostics::error(std::string_view code, SourceLoc loc, std::string message, std::vector<DiagnosticNote> notes) {
    report({Severity::Error, std::string(code), loc, std::move(message), std::move(notes)});
}

void Diagnostics::warning(std::string_view code, SourceLoc loc, std::string message,
                          std::vector<DiagnosticNote> notes) {
    report({Severity::Warning, std::string(code), loc, std::move(message), std::move(notes)});
}

std::vector<Diagnostic> Diagnostics::take() {
    // The cap line has neither a code nor a location; it stays last.
    auto key = [](const Diagnostic& d) {
        const bool capLine = d.code.empty() && d.loc.line == 0;
        return std::make_tuple(capLine, d.loc.line, d.loc.column);
    };
    std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
    return std::move(diagnostics_);
}

} // namespace voxc

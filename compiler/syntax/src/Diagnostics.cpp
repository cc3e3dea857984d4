#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <algorithm>
#include <cctype>
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

// "unknown grammar or field 'wether'" of "unknown grammar or field 'wether' in the pipeline; did
// you mean ...": what an unknown name's error says about the name, or empty for other diagnostics.
std::string unknownName(const Diagnostic& d) {
    if (d.severity != Severity::Error || d.code != "E0002" || !d.message.starts_with("unknown ")) return {};
    const size_t open = d.message.find('\'');
    const size_t close = open == std::string::npos ? open : d.message.find('\'', open + 1);
    if (close == std::string::npos) return {};
    return fmt::format("{}\x1f{}", d.file ? d.file->path() : std::string(), d.message.substr(0, close + 1));
}

} // namespace

void Diagnostics::report(Diagnostic diagnostic) {
    if (truncated_ && diagnostic.severity == Severity::Error) return;
    if (!seen_.insert(identity(diagnostic)).second) return;
    // An unknown name is reported where it is first used; its other uses would only repeat it.
    if (const std::string name = unknownName(diagnostic); !name.empty() && !seen_.insert(name).second) return;
    if (diagnostic.severity == Severity::Error && errorCount_ == kMaxErrors) {
        truncated_ = true;
        diagnostics_.push_back({Severity::Error, "", {},
                                fmt::format("too many errors; stopping after the first {}", kMaxErrors), {}, nullptr});
        return;
    }
    if (diagnostic.severity == Severity::Error) ++errorCount_;
    diagnostics_.push_back(std::move(diagnostic));
}

void Diagnostics::error(std::string_view code, SourceLoc loc, std::string message, std::vector<DiagnosticNote> notes,
                        std::vector<FixIt> fixits) {
    report({Severity::Error, std::string(code), loc, std::move(message), std::move(notes), nullptr, std::move(fixits)});
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

namespace {

bool isIdentifier(std::string_view text) {
    if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_')) return false;
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

} // namespace

void addSuggestionFixIts(std::vector<Diagnostic>& diagnostics, const SourceFile& source) {
    constexpr std::string_view prefix = "; did you mean '";
    constexpr std::string_view suffix = "'?";
    for (Diagnostic& diagnostic : diagnostics) {
        const std::string& message = diagnostic.message;
        if (diagnostic.loc.line == 0 || !diagnostic.fixits.empty() || !message.ends_with(suffix)) continue;
        const size_t start = message.rfind(prefix);
        if (start == std::string::npos) continue;
        const std::string suggestion =
            message.substr(start + prefix.size(), message.size() - suffix.size() - start - prefix.size());
        const SourceFile& file = diagnostic.file ? *diagnostic.file : source;
        if (diagnostic.loc.line > file.lineCount()) continue;
        const std::string_view line = file.line(diagnostic.loc.line);
        const size_t column = diagnostic.loc.column - 1;
        if (diagnostic.loc.column == 0 || column + diagnostic.loc.length > line.size()) continue;
        const std::string_view located = line.substr(column, diagnostic.loc.length);
        // Certain only when the caret covers the misspelt name itself, quoted before the suggestion.
        if (!isIdentifier(located) || !isIdentifier(suggestion) || located == suggestion ||
            message.substr(0, start).find(fmt::format("'{}'", located)) == std::string::npos)
            continue;
        diagnostic.fixits.push_back({diagnostic.loc, suggestion});
    }
}

} // namespace voxc

#pragma once
// Diagnostics are typed values; turning them into text is a separate step (render), so tests
// can assert on codes and locations and the CLI can choose how to print them.
#include "voxc/core/SourceLoc.h"

#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace voxc {

class SourceFile;

enum class Severity : uint8_t { Error, Warning, Note };

const char* severityName(Severity severity); // "error", "warning", "note"

// A remark attached to a diagnostic, e.g. where the other half of a conflict is.
// A note whose loc.line is 0 has no location.
struct DiagnosticNote {
    SourceLoc loc;
    std::string message;
};

// An edit the diagnostic is sure fixes it: replace the `loc.length` characters at `loc` with
// `replacement` (length 0: insert before loc.column). Offered only where there is one fix: a
// misspelt name with a single close candidate, a missing ';'.
struct FixIt {
    SourceLoc loc;
    std::string replacement;
};

// code is a stable identifier such as "E0004" or "W0201" (empty only for the final
// "too many errors" line). loc.line == 0 means the diagnostic is about the whole file.
// `file` is set when loc lies in another file than the one being checked (an L-system rule
// file it imports); such diagnostics and their notes are rendered against that file.
struct Diagnostic {
    Severity severity = Severity::Error;
    std::string code;
    SourceLoc loc;
    std::string message;
    std::vector<DiagnosticNote> notes;
    std::shared_ptr<const SourceFile> file;
    std::vector<FixIt> fixits{}; // in `file` when set, like loc
};

// Adds the fix-it "replace the name with the suggestion" to each diagnostic whose message ends in
// "; did you mean 'NAME'?" and whose location covers exactly a name the message quotes (the
// misspelt one). Run once the diagnostics are complete; `source` is the checked file.
void addSuggestionFixIts(std::vector<Diagnostic>& diagnostics, const SourceFile& source);

// Collects diagnostics, drops exact duplicates, and stops recording errors after kMaxErrors,
// appending one final "too many errors" diagnostic instead. take() hands them over in source
// order (file-level ones first, those located in other files after the checked file's, the
// "too many errors" line last), whatever order the checker's
// passes found them in.
class Diagnostics {
public:
    static constexpr int kMaxErrors = 20;

    void report(Diagnostic diagnostic);
    void error(std::string_view code, SourceLoc loc, std::string message, std::vector<DiagnosticNote> notes = {},
               std::vector<FixIt> fixits = {});
    void warning(std::string_view code, SourceLoc loc, std::string message, std::vector<DiagnosticNote> notes = {});

    bool hasErrors() const { return errorCount_ > 0; }
    int errorCount() const { return errorCount_; }
    const std::vector<Diagnostic>& all() const { return diagnostics_; }
    std::vector<Diagnostic> take();

private:
    std::vector<Diagnostic> diagnostics_;
    std::unordered_set<std::string> seen_; // every diagnostic reported, for dropping duplicates
    int errorCount_ = 0;
    bool truncated_ = false;
};

// One diagnostic (against diagnostic.file when set, else `source`) in the form
//   path:line:col: error E0004: message
//      12 |     symbol {
//         |     ^~~~~~
//         |     symbols          (a fix-it on the line, under the text it replaces)
// followed by its notes in the same form. Without a location: `path: error E0100: message`.
// Ends with a newline.
std::string render(const Diagnostic& diagnostic, const SourceFile& source);

// Every diagnostic in order, each rendered as above.
std::string renderAll(const std::vector<Diagnostic>& diagnostics, const SourceFile& source);

} // namespace voxc

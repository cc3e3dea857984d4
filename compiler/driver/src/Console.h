#pragma once
// How a verb talks to the terminal or to a tool: diagnostics as text or as JSON lines
// (--diagnostics-format), status lines silenced by -q/--quiet, details added by -v/--verbose.
// One verb runs per process, so its flags set one process-wide Console before its action runs.
#include "voxc/core/Errors.h"
#include "voxc/syntax/Diagnostics.h"

#include <CLI/CLI.hpp>
#include <ostream>
#include <string_view>
#include <vector>

namespace voxc::driver {

enum class DiagnosticsFormat { Text, Json };
enum class Verbosity { Quiet, Normal, Verbose };

struct ConsoleOptions {
    DiagnosticsFormat format = DiagnosticsFormat::Text;
    Verbosity verbosity = Verbosity::Normal;
};

// The options the flags of the running verb set.
ConsoleOptions& consoleOptions();

// -q/--quiet, -v/--verbose (exclusive) and --diagnostics-format text|json.
void addConsoleFlags(CLI::App& command);

// Where a verb reports what it did ("wrote PATH", "FILE: ok"): stderr, or nowhere under -q.
std::ostream& status();
// Details only -v asks for (inputs read, timings): stderr under -v, else nowhere.
std::ostream& detail();

// The checker's diagnostics, in order, to stderr: rendered with source lines and carets, or one
// JSON object per line (voxc/syntax/DiagnosticJson.h). Warnings and errors print under -q too.
void printDiagnostics(const std::vector<Diagnostic>& diagnostics, const SourceFile& source);

// The error that ends a command after its diagnostics were printed: "a.vox: 2 errors" in text;
// under --diagnostics-format json main prints a summary record instead of one more error,
// {"summary": {"file": "a.vox", "errors": 2, "warnings": 0}}.
struct DiagnosticsFailed : UserError {
    DiagnosticsFailed(std::string path, size_t errors, size_t warnings, bool warningsAsErrors = false);
    std::string path;
    size_t errors = 0;
    size_t warnings = 0;
};

// Counts the errors and warnings of `diagnostics` and throws DiagnosticsFailed when there is an
// error, or a warning under `warningsAsErrors` (--werror).
void failOnErrors(const std::string& path, const std::vector<Diagnostic>& diagnostics, bool warningsAsErrors = false);

void printDiagnosticsSummary(const DiagnosticsFailed& failure);

// The line main prints for an error that ends the command ("voxc: error: ...", or a JSON line
// without code or location); `internal` marks a bug in voxc.
void printFatalError(std::string_view message, bool internal);

} // namespace voxc::driver

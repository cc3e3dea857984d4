#include "Console.h"
#include "voxc/syntax/DiagnosticJson.h"

#include <nlohmann/json.hpp>

#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

// A stream that drops what it is given: status() under -q, detail() without -v.
class NullBuffer : public std::streambuf {
protected:
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize count) override { return count; }
};

std::ostream& nullStream() {
    static NullBuffer buffer;
    static std::ostream stream(&buffer);
    return stream;
}

void printJsonLine(const nlohmann::ordered_json& object) {
    // Messages quote the user's text, which the checker has already required to be UTF-8;
    // replacing stays safe should one not be.
    std::cerr << object.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

} // namespace

ConsoleOptions& consoleOptions() {
    static ConsoleOptions options;
    return options;
}

void addConsoleFlags(CLI::App& command) {
    CLI::Option* quiet = command.add_flag_callback(
        "-q,--quiet", [] { consoleOptions().verbosity = Verbosity::Quiet; },
        "Print only warnings and errors");
    CLI::Option* verbose = command.add_flag_callback(
        "-v,--verbose", [] { consoleOptions().verbosity = Verbosity::Verbose; },
        "Also print the files read and the time each step took");
    quiet->excludes(verbose);
    command
        .add_option_function<std::string>(
            "--diagnostics-format",
            [](const std::string& format) {
                consoleOptions().format = format == "json" ? DiagnosticsFormat::Json : DiagnosticsFormat::Text;
            },
            "text (default: file:line:col, the source line and a caret) or json (one object per line)")
        ->check(CLI::IsMember({"text", "json"}));
}

std::ostream& status() {
    return consoleOptions().verbosity == Verbosity::Quiet ? nullStream() : std::cerr;
}

std::ostream& detail() {
    return consoleOptions().verbosity == Verbosity::Verbose ? std::cerr : nullStream();
}

void printDiagnostics(const std::vector<Diagnostic>& diagnostics, const SourceFile& source) {
    for (const Diagnostic& diagnostic : diagnostics) {
        if (consoleOptions().format == DiagnosticsFormat::Json)
            std::cerr << renderJson(diagnostic, source) << "\n";
        else
            std::cerr << render(diagnostic, source);
    }
}

namespace {

std::string describeFailure(const std::string& path, size_t errors, size_t warnings, bool warningsAsErrors) {
    if (errors == 0 && warningsAsErrors)
        return fmt::format("{}: {} warning{} (--werror)", path, warnings, warnings == 1 ? "" : "s");
    return fmt::format("{}: {} error{}", path, errors, errors == 1 ? "" : "s");
}

} // namespace

DiagnosticsFailed::DiagnosticsFailed(std::string path, size_t errors, size_t warnings, bool warningsAsErrors)
    : UserError(describeFailure(path, errors, warnings, warningsAsErrors)), path(std::move(path)), errors(errors),
      warnings(warnings) {}

void failOnErrors(const std::string& path, const std::vector<Diagnostic>& diagnostics, bool warningsAsErrors) {
    size_t errors = 0;
    size_t warnings = 0;
    for (const Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.severity == Severity::Error) ++errors;
        if (diagnostic.severity == Severity::Warning) ++warnings;
    }
    if (errors > 0 || (warningsAsErrors && warnings > 0))
        throw DiagnosticsFailed(path, errors, warnings, warningsAsErrors);
}

void printDiagnosticsSummary(const DiagnosticsFailed& failure) {
    if (consoleOptions().format == DiagnosticsFormat::Json) {
        printJsonLine({{"summary", {{"file", failure.path}, {"errors", failure.errors}, {"warnings", failure.warnings}}}});
        return;
    }
    std::cerr << "voxc: error: " << failure.what() << "\n";
}

void printFatalError(std::string_view message, bool internal) {
    if (consoleOptions().format == DiagnosticsFormat::Json) {
        printJsonLine({{"code", ""},
                       {"severity", "error"},
                       {"file", nullptr},
                       {"range", nullptr},
                       {"message", internal ? std::string(message) + " (a bug in voxc; please report it)"
                                            : std::string(message)},
                       {"notes", nlohmann::ordered_json::array()}});
        return;
    }
    if (internal)
        std::cerr << "voxc: " << message << "\nThis is a bug in voxc; please report it with the input file.\n";
    else
        std::cerr << "voxc: error: " << message << "\n";
}

} // namespace voxc::driver

#include "Console.h"
#include "DiagnosticJson.h"

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
            printJsonLine(diagnosticJson(diagnostic, source));
        else
            std::cerr << render(diagnostic, source);
    }
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

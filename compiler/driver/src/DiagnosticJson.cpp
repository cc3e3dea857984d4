#include "DiagnosticJson.h"

namespace voxc::driver {

namespace {

nlohmann::ordered_json rangeJson(SourceLoc loc) {
    if (loc.line == 0) return nullptr;
    using nlohmann::ordered_json;
    return ordered_json{{"start", ordered_json{{"line", loc.line}, {"column", loc.column}}},
                        {"end", ordered_json{{"line", loc.line}, {"column", loc.column + loc.length}}}};
}

} // namespace

nlohmann::ordered_json diagnosticJson(const Diagnostic& diagnostic, const SourceFile& checked) {
    // Notes lie in the diagnostic's file, as render() shows them.
    const std::string& file = diagnostic.file ? diagnostic.file->path() : checked.path();
    nlohmann::ordered_json notes = nlohmann::ordered_json::array();
    for (const DiagnosticNote& note : diagnostic.notes)
        notes.push_back({{"file", file}, {"range", rangeJson(note.loc)}, {"message", note.message}});
    return {{"code", diagnostic.code},         {"severity", severityName(diagnostic.severity)},
            {"file", file},                    {"range", rangeJson(diagnostic.loc)},
            {"message", diagnostic.message},   {"notes", std::move(notes)}};
}

} // namespace voxc::driver

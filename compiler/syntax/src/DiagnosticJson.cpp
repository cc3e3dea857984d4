#include "voxc/syntax/DiagnosticJson.h"

#include <nlohmann/json.hpp>

namespace voxc {

namespace {

nlohmann::ordered_json rangeJson(SourceLoc loc) {
    if (loc.line == 0) return nullptr;
    using nlohmann::ordered_json;
    return ordered_json{{"start", ordered_json{{"line", loc.line}, {"column", loc.column}}},
                        {"end", ordered_json{{"line", loc.line}, {"column", loc.column + loc.length}}}};
}

} // namespace

std::string renderJson(const Diagnostic& diagnostic, const SourceFile& checked) {
    // Notes lie in the diagnostic's file, as render() shows them.
    const std::string& file = diagnostic.file ? diagnostic.file->path() : checked.path();
    nlohmann::ordered_json notes = nlohmann::ordered_json::array();
    for (const DiagnosticNote& note : diagnostic.notes)
        notes.push_back({{"file", file}, {"range", rangeJson(note.loc)}, {"message", note.message}});
    nlohmann::ordered_json fixits = nlohmann::ordered_json::array();
    for (const FixIt& fixit : diagnostic.fixits)
        fixits.push_back({{"range", rangeJson(fixit.loc)}, {"replacement", fixit.replacement}});
    const nlohmann::ordered_json object = {{"code", diagnostic.code},       {"severity", severityName(diagnostic.severity)},
                                           {"file", file},                  {"range", rangeJson(diagnostic.loc)},
                                           {"message", diagnostic.message}, {"notes", std::move(notes)},
                                           {"fixits", std::move(fixits)}};
    return object.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

} // namespace voxc

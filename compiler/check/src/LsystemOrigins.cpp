#include "LsystemOrigins.h"

#include <fmt/format.h>

namespace voxc::check {

namespace {

// The string a `where` names: the axiom, or "production Z #2" / "macro Q #1".
std::optional<std::pair<std::string_view, lsystem::StringRole>> namedString(const lsystem::Definition& definition,
                                                                           const std::string& where) {
    if (where == "axiom") return std::pair{std::string_view(definition.axiom), lsystem::StringRole::Axiom};
    const bool production = where.starts_with("production ");
    const bool macro = where.starts_with("macro ");
    const size_t hash = where.find(" #");
    if ((!production && !macro) || hash == std::string::npos || hash < 2) return std::nullopt;
    const char symbol = where[hash - 1];
    const auto& table = production ? definition.productions : definition.macros;
    auto it = table.find(symbol);
    const size_t index = std::stoul(where.substr(hash + 2)) - 1;
    if (it == table.end() || index >= it->second.size()) return std::nullopt;
    return std::pair{std::string_view(it->second[index].text),
                     production ? lsystem::StringRole::Production : lsystem::StringRole::Substitute};
}

} // namespace

void LsystemOrigins::report(Context& context, const lsystem::Definition& definition,
                            const lsystem::DefinitionProblem& problem) const {
    auto emit = [&](const LsystemOrigin& origin, SourceLoc loc) {
        Diagnostic diagnostic{Severity::Error, problem.code, loc, problem.message, {}, origin.file};
        context.diagnostics.report(std::move(diagnostic));
    };
    // A problem inside a string (every string code but E0007, which is its weight) is located
    // at its character: checkString finds the same problem again, with its offset.
    if (auto string = strings.find(problem.where); string != strings.end() && problem.code != "E0007") {
        if (auto named = namedString(definition, problem.where)) {
            if (auto found = lsystem::checkString(definition, named->first, named->second); found && found->code == problem.code) {
                SourceLoc loc = string->second.loc;
                loc.column += uint32_t(found->offset);
                loc.length = 1;
                emit(string->second, loc);
                return;
            }
        }
    }
    if (auto place = places.find(problem.where); place != places.end()) {
        emit(place->second, place->second.loc);
        return;
    }
    // "production Z #2" without a place of its own falls back to "production Z".
    if (size_t hash = problem.where.find(" #"); hash != std::string::npos)
        if (auto place = places.find(problem.where.substr(0, hash)); place != places.end()) {
            emit(place->second, place->second.loc);
            return;
        }
    emit(fallback, fallback.loc);
}

} // namespace voxc::check

#include "LsystemInputs.h"
#include "Console.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Suggest.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/syntax/Diagnostics.h"

#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

CheckResult loadChecked(const std::string& path) {
    CheckResult result = checkFile(path);
    printDiagnostics(result.diagnostics, result.source);
    failOnErrors(path, result.diagnostics);
    VOXC_ASSERT(result.program); // a check without errors has a program
    return result;
}

const CheckedLsystem& findLsystem(const std::vector<CheckedLsystem>& lsystems, const std::string& path,
                                  const std::string& name) {
    std::string names;
    std::vector<std::string_view> candidates;
    for (const CheckedLsystem& lsystem : lsystems) {
        if (lsystem.name == name) return lsystem;
        if (!names.empty()) names += ", ";
        names += lsystem.name;
        candidates.push_back(lsystem.name);
    }
    throw UserError(fmt::format("{}: no lsystem named '{}'{} ({})", path, name, didYouMean(name, candidates),
                                names.empty() ? "the file declares none" : "it declares: " + names));
}

[[noreturn]] void reportLimit(const CheckResult& result, const CheckedLsystem& lsystem,
                              const lsystem::LimitError& error) {
    Diagnostic diagnostic{Severity::Error, "E0012", lsystem.loc,
                          fmt::format("lsystem '{}': {}", lsystem.name, error.what()), {}, nullptr};
    std::cerr << render(diagnostic, result.source);
    throw UserError(fmt::format("{}: 1 error", result.source.path()));
}

std::string expansionTrace(const CheckedLsystem& lsystem, uint64_t maxLines, uint64_t& printed) {
    using namespace lsystem;
    std::string out;
    const auto line = [&](std::string text) {
        if (printed >= maxLines) return;
        ++printed;
        out += text + "\n";
    };
    Expansion expansion;
    try {
        expansion = expand(lsystem.definition, ExpandOptions{true});
    } catch (const LimitError& error) {
        line(fmt::format("lsystem {}: not expanded: {}", lsystem.name, error.what()));
        return out;
    }
    for (const Choice& choice : expansion.choices) {
        const auto& table = choice.macro ? lsystem.definition.macros : lsystem.definition.productions;
        const Alternative& taken = table.at(choice.symbol).at(choice.alternative);
        line(fmt::format("lsystem {} expansion {}: {} {} at {} took {} {} of {}: \"{}\" {}", lsystem.name,
                         choice.expansion, choice.macro ? "macro" : "symbol", choice.symbol, choice.position,
                         choice.macro ? "substitute" : "production", choice.alternative + 1,
                         table.at(choice.symbol).size(), taken.text, symbolTypeName(taken.type)));
    }
    for (size_t k = 0; k < expansion.lengths.size(); ++k)
        line(fmt::format("lsystem {} after {} expansion{}: {} symbols", lsystem.name, k, k == 1 ? "" : "s",
                         expansion.lengths[k]));
    return out;
}

std::pair<std::string, std::string> splitReference(const std::string& reference) {
    const size_t colon = reference.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == reference.size())
        throw UserError(fmt::format("'{}': name an lsystem as FILE:NAME, e.g. caves.vox:net", reference));
    return {reference.substr(0, colon), reference.substr(colon + 1)};
}

} // namespace voxc::driver

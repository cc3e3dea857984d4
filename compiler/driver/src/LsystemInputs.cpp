#include "LsystemInputs.h"

#include "voxc/core/Errors.h"
#include "voxc/syntax/Diagnostics.h"

#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

CheckResult loadChecked(const std::string& path) {
    CheckResult result = checkFile(path);
    size_t errors = 0;
    for (const Diagnostic& diagnostic : result.diagnostics) {
        std::cerr << render(diagnostic, result.source);
        errors += diagnostic.severity == Severity::Error;
    }
    if (result.hasErrors() || !result.program)
        throw UserError(fmt::format("{}: {} error{}", path, errors, errors == 1 ? "" : "s"));
    return result;
}

const CheckedLsystem& findLsystem(const CheckResult& result, const std::string& path, const std::string& name) {
    std::string names;
    for (const CheckedLsystem& lsystem : result.lsystems) {
        if (lsystem.name == name) return lsystem;
        if (!names.empty()) names += ", ";
        names += lsystem.name;
    }
    throw UserError(fmt::format("{}: no lsystem named '{}' ({})", path, name,
                                names.empty() ? "the file declares none" : "it declares: " + names));
}

[[noreturn]] void reportLimit(const CheckResult& result, const CheckedLsystem& lsystem,
                              const lsystem::LimitError& error) {
    Diagnostic diagnostic{Severity::Error, "E0012", lsystem.loc,
                          fmt::format("lsystem '{}': {}", lsystem.name, error.what()), {}, nullptr};
    std::cerr << render(diagnostic, result.source);
    throw UserError(fmt::format("{}: 1 error", result.source.path()));
}

std::pair<std::string, std::string> splitReference(const std::string& reference) {
    const size_t colon = reference.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == reference.size())
        throw UserError(fmt::format("'{}': name an lsystem as FILE:NAME, e.g. caves.vox:net", reference));
    return {reference.substr(0, colon), reference.substr(colon + 1)};
}

} // namespace voxc::driver

#include "voxc/check/LoadPackage.h"

#include "voxc/check/Check.h"
#include "voxc/codegen/PackageReader.h"
#include "voxc/core/Errors.h"
#include "voxc/stages/Pipeline.h"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fmt/format.h>

namespace voxc {

namespace {

// The package's copy of its sources, checked with the settings it was compiled with.
Program packagedProgram(const codegen::PackageContents& contents) {
    CheckOptions options;
    options.seed = contents.seed;
    // `voxc compile --max-work` may have accepted more work than the default budget.
    options.limits.maxWork = INT64_MAX;
    // Rule files and the files heightmap and mesh blocks read: the package's copies.
    options.readRuleFile = [&](const std::string& path) -> std::optional<std::string> {
        for (const codegen::ImportedFile& file : contents.source.imports)
            if (file.path == path) return file.text;
        return std::nullopt;
    };
    options.readInputFile = options.readRuleFile;
    CheckResult result = checkSource(SourceFile(contents.source.fileName, contents.source.text), options);
    if (result.hasErrors() || !result.program)
        throw UserError(fmt::format("cannot load package '{}': its copy of {} does not check:\n{}", contents.directory,
                                    contents.source.fileName, result.rendered()));
    Program program = std::move(*result.program);
    program.world.chunkSize = contents.chunkSize;
    return program;
}

} // namespace

codegen::PackageSource packageSource(const std::string& path, const std::string& text,
                                     const std::vector<CheckedLsystem>& lsystems, const std::vector<InputFile>& inputs) {
    codegen::PackageSource source{std::filesystem::path(path).filename().string(), text, {}};
    const auto copied = [&](const std::string& name) {
        return std::any_of(source.imports.begin(), source.imports.end(),
                           [&](const codegen::ImportedFile& file) { return file.path == name; });
    };
    for (const CheckedLsystem& lsystem : lsystems)
        if (!lsystem.rulesPath.empty() && !copied(lsystem.rulesName))
            source.imports.push_back({lsystem.rulesName, lsystem.rulesText});
    for (const InputFile& input : inputs)
        if (!copied(input.name)) source.imports.push_back({input.name, *input.bytes});
    return source;
}

LoadedPackage loadPackage(const std::string& directory) {
    const codegen::PackageContents contents = codegen::readPackage(directory);
    LoadedPackage loaded{packagedProgram(contents), {}};
    {
        const codegen::PackagedSpirvScope spirv(contents);
        loaded.package = compileProgram(loaded.program);
    }
    codegen::verifyRebuiltPackage(loaded.package, contents);
    return loaded;
}

} // namespace voxc

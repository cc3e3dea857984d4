#include "OutputPaths.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <sys/stat.h>

namespace voxc::driver {

namespace fs = std::filesystem;

namespace {

fs::path resolved(const std::string& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : canonical;
}

} // namespace

bool sameFile(const std::string& a, const std::string& b) {
    struct stat statA {}, statB {};
    const bool aExists = ::stat(a.c_str(), &statA) == 0;
    const bool bExists = ::stat(b.c_str(), &statB) == 0;
    if (aExists && bExists) return statA.st_dev == statB.st_dev && statA.st_ino == statB.st_ino;
    if (aExists != bExists) return false;
    return resolved(a) == resolved(b);
}

void refuseClashingPaths(std::span<const RolePath> inputs, std::span<const RolePath> outputs) {
    for (size_t o = 0; o < outputs.size(); ++o) {
        const RolePath& output = outputs[o];
        if (output.path.empty()) continue;
        std::error_code ec;
        if (!output.isDirectory && fs::is_directory(output.path, ec))
            throw UserError(fmt::format("{} '{}' is a directory: give a file name", output.role, output.path));
        for (const RolePath& input : inputs)
            if (!input.path.empty() && sameFile(output.path, input.path))
                throw UserError(fmt::format("{} '{}' is {} '{}': voxc never writes over a file it reads", output.role,
                                            output.path, input.role, input.path));
        for (size_t other = 0; other < o; ++other)
            if (!outputs[other].path.empty() && sameFile(output.path, outputs[other].path))
                throw UserError(fmt::format("{} '{}' and {} '{}' are the same file", outputs[other].role,
                                            outputs[other].path, output.role, output.path));
    }
}

void refuseInputsInside(const RolePath& directory, std::span<const RolePath> inputs) {
    fs::path root = resolved(directory.path);
    if (root.filename().empty()) root = root.parent_path(); // "pkg/" -> "pkg"
    for (const RolePath& input : inputs) {
        const fs::path file = resolved(input.path);
        const auto [rootEnd, fileAt] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
        if (rootEnd == root.end())
            throw UserError(fmt::format("{} '{}' contains {} '{}': voxc never writes over a file it reads",
                                        directory.role, directory.path, input.role, input.path));
    }
}

} // namespace voxc::driver

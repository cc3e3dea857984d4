#include "Depfile.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::driver {

namespace {

// The package directory as typed, without trailing slashes ("pkg/" -> "pkg"; "/" stays).
std::string withoutTrailingSlashes(std::string path) {
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    return path;
}

std::string escaped(const std::string& path) {
    if (path.find('\n') != std::string::npos || path.find('\r') != std::string::npos)
        throw UserError(fmt::format("a depfile cannot name '{}': it contains a line break", path));
    std::string out;
    for (const char c : path) {
        if (c == ' ' || c == '#') out += '\\';
        if (c == '$') out += '$';
        out += c;
    }
    return out;
}

} // namespace

void addDepfileFlags(CLI::App& command, DepfileOptions& options) {
    command.add_flag("--MD", options.write, "Also write a make/ninja depfile listing the .vox and its rule files");
    command.add_option("--MF", options.path, "The depfile's path (default: PKG_DIR.d); implies -MD");
    command.add_option("--MT", options.target, "The target the depfile names (default: PKG_DIR/manifest.json); implies -MD");
}

std::vector<std::string> spellDepfileFlagsLong(int argc, char** argv) {
    std::vector<std::string> arguments(argv, argv + argc);
    for (size_t i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == "--") break; // what follows is a file name, whatever it looks like
        if (arguments[i] == "-MD" || arguments[i] == "-MF" || arguments[i] == "-MT") arguments[i].insert(0, "-");
    }
    return arguments;
}

std::vector<std::string> packageInputs(const std::string& file, const std::vector<CheckedLsystem>& lsystems,
                                       const std::vector<InputFile>& files) {
    std::vector<std::string> inputs{file};
    const auto add = [&](const std::string& path) {
        if (std::find(inputs.begin(), inputs.end(), path) == inputs.end()) inputs.push_back(path);
    };
    for (const CheckedLsystem& lsystem : lsystems)
        if (!lsystem.rulesPath.empty()) add(lsystem.rulesPath);
    for (const InputFile& input : files) add(input.path);
    return inputs;
}

std::string formatDepfile(const std::string& target, const std::vector<std::string>& inputs) {
    std::string text = escaped(target) + ":";
    for (const std::string& input : inputs) text += " \\\n  " + escaped(input);
    return text + "\n";
}

std::string depfilePath(const DepfileOptions& options, const std::string& packageDir) {
    return options.path.empty() ? withoutTrailingSlashes(packageDir) + ".d" : options.path;
}

std::string depfileTarget(const DepfileOptions& options, const std::string& packageDir) {
    return options.target.empty() ? withoutTrailingSlashes(packageDir) + "/manifest.json" : options.target;
}

} // namespace voxc::driver

#pragma once
// Helpers every verb shares: loading and checking a file, printing diagnostics, and the
// flags that override the file's world settings.
#include "voxc/program/Program.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace voxc::driver {

struct WorldOverrides {
    std::optional<uint32_t> seed;
    std::optional<int32_t> chunk;
};

void addWorldOverrideFlags(CLI::App& command, WorldOverrides& overrides);

// Parses and checks `path`, prints every diagnostic to stderr and throws UserError when there
// are errors (the message says how many). Applies the overrides to the checked program.
Program loadProgram(const std::string& path, const WorldOverrides& overrides, bool warningsAsErrors = false);

// Output file names: the extension must be one of `extensions` (e.g. {".ply", ".obj"}).
void requireExtension(const std::string& path, std::initializer_list<const char*> extensions, const char* what);

} // namespace voxc::driver

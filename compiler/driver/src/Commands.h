#pragma once
// One function per verb: each adds its subcommand, flags and action to the app.
#include <CLI/CLI.hpp>

namespace voxc::driver {

void addCheckCommand(CLI::App& app);
void addCompileCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addInterpCommand(CLI::App& app);
void addExploreCommand(CLI::App& app);
void addLsystemCommand(CLI::App& app);
void addEvolveCommand(CLI::App& app);
void addTerrainCommand(CLI::App& app);
void addLspCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addWorldCommand(CLI::App& app);
void addViewCommand(CLI::App& app);

} // namespace voxc::driver

#pragma once
// Helpers every verb shares: loading and checking a file, printing diagnostics, and the
// flags that override the file's world settings.
#include "voxc/check/Check.h"
#include "voxc/generators/curves/Solvers.h"
#include "voxc/generators/terrain/Terrain.h"
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace voxc::driver {

struct WorldOverrides {
    std::optional<uint32_t> seed;
    std::optional<int32_t> chunk;
    std::optional<double> maxWork; // replaces Limits::maxWork (--max-work; `1e12` is accepted)
    std::optional<std::pair<glm::ivec3, glm::ivec3>> region; // CheckOptions::region (--region, world voxels)
    curves::Solvers curvesSolver; // stages::SolveOptions::solvers of the run (run --solve-on); empty members: the host
    terrain::ErosionRunner erosionRunner; // stages::SolveOptions::erosionRunner (run --solve-on); empty: the host
    bool keepSolveChannels = false;    // stages::SolveOptions::keepChannels of the run (--dump)
};

// --seed, --chunk and --max-work.
void addWorldOverrideFlags(CLI::App& command, WorldOverrides& overrides);
// --device: the Vulkan device that runs the kernels (parsed by vulkan::selectDevice's rules).
void addDeviceFlag(CLI::App& command, std::string& device);
// --max-work alone (for `check`, which runs nothing).
void addMaxWorkFlag(CLI::App& command, WorldOverrides& overrides);

// Parses and checks `path`, prints every diagnostic to stderr (Console.h) and throws UserError when there
// are errors (the message says how many). Applies the overrides to the checked program.
// `sourceText`, when given, receives the text that was checked; `lsystems` the checked lsystem blocks.
Program loadProgram(const std::string& path, const WorldOverrides& overrides, bool warningsAsErrors = false,
                    std::string* sourceText = nullptr, std::vector<CheckedLsystem>* lsystems = nullptr);

// One line counting the solid voxels (density > iso) of each material id, ascending id, e.g.
// "solid voxels by material: none 12, rock 5120, sand 733"; materials with no solid voxel are left out.
std::string formatMaterialCounts(const Program& program, const DenseGrid& grid, float iso);

// Adds the --voxels (float densities) and --materials (uint8 ids) files of `grid` to `outputs`;
// an empty path is skipped. The caller commits the set and reports the files (reportWritten).
void writeGridFiles(OutputFiles& outputs, const std::string& voxelsPath, const std::string& materialsPath,
                    const DenseGrid& grid);

// "wrote PATH" on status() for each non-empty path, after the set was committed.
void reportWritten(std::initializer_list<std::string> paths);

// Output file names: the extension must be one of `extensions` (e.g. {".ply", ".obj"}).
void requireExtension(const std::string& path, std::initializer_list<const char*> extensions, const char* what);

} // namespace voxc::driver

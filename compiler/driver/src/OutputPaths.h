#pragma once
// Checked before a command does any work: no output may be one of its inputs or another of its
// outputs, so `voxc run terrain.ply -o terrain.ply` cannot overwrite its own input.
#include <span>
#include <string>

namespace voxc::driver {

// A path as the command line named it: `role` is the flag or "the input", for messages.
struct RolePath {
    std::string role;
    std::string path;
    bool isDirectory = false; // an output directory (evolve's -o), not a file
};

// True when both name one file: the same device and inode when both exist (so a symlink or a
// hard link to a file is that file), otherwise the same absolute path after resolving the links
// of the part that exists (std::filesystem::weakly_canonical).
bool sameFile(const std::string& a, const std::string& b);

// UserError naming the two roles when an output is an input or two outputs are one file, or
// when an output file names an existing directory (refused before any work, not at write time).
// Empty paths (flags not given) are skipped.
void refuseClashingPaths(std::span<const RolePath> inputs, std::span<const RolePath> outputs);

// UserError when `directory` is, or contains, one of the inputs (a package directory is replaced as a whole).
void refuseInputsInside(const RolePath& directory, std::span<const RolePath> inputs);

} // namespace voxc::driver

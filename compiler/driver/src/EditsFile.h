#pragma once
// Edits as data (`voxc run|interp --edits FILE`): a JSON array of sphere brushes replayed, in order,
// on the generated grid before meshing and writing (docs/cli.md, "Edits files"):
//   [{"op": "carve", "center": [40.5, 20, 33], "radius": 6, "softness": 2},
//    {"op": "add", "center": [10, 30, 12], "radius": 3, "material": "rock"}]
// Errors are located diagnostics: JSON syntax E0001 at the parser's position; at the offending key
// (or the edit) an unknown key E0008, a missing one E0009, a value of the wrong type E0010, an
// unknown op E0011, a value out of range E0007, a material the program does not declare E0002;
// more than kMaxEdits edits, or brushes visiting more than kMaxEditVoxels voxels, E0012.
#include "voxc/edit/Brush.h"
#include "voxc/program/Program.h"
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace voxc::driver {

// --edits FILE on `run` and `interp`.
void addEditsFlag(CLI::App& command, std::string& path);

inline constexpr size_t kMaxEdits = 100000;
// The file's size: room for kMaxEdits edits as the viewer saves them (about 80 bytes each).
inline constexpr size_t kMaxEditsFileBytes = size_t(16) << 20;
inline constexpr float kMaxBrushRadius = 4096.0f;
inline constexpr float kMaxBrushSoftness = 256.0f;
inline constexpr float kMaxBrushCoordinate = 16777216.0f; // 2^24: integer positions stay exact in float
// The work of replaying a file: the voxels its brushes' support boxes cover inside the world's
// grid, summed over the edits (each voxel costs a square root and a few compares, a few ns).
inline constexpr uint64_t kMaxEditVoxels = 1000000000;

// `program`: its materials, which an add's "material" names, and its world's grid, which bounds the work.
std::vector<Brush> parseEdits(const SourceFile& source, Diagnostics& diagnostics, const Program& program);
// Reads and parses `path`; prints every diagnostic to stderr and throws UserError when there are errors.
std::vector<Brush> loadEdits(const std::string& path, const Program& program);

// Applies the brushes in order; returns how many changed at least one voxel.
size_t applyEdits(ChunkedGrid& grid, const std::vector<Brush>& edits);
size_t applyEdits(DenseGrid& grid, glm::ivec3 origin, const std::vector<Brush>& edits);
// "edits: 3 applied on the host, 2 of them changed voxels\n" (empty without edits).
std::string describeEdits(size_t applied, size_t changed);

} // namespace voxc::driver

#pragma once
// Files a .vox names as modelling primitives (docs/language.md, "Heightmaps", "Meshes"): height
// images read into float grids, triangle meshes read and turned into signed distances. The
// checker reads the bytes (and tracks the file: depfile, package, cache key) and locates the
// errors these functions throw at the block's `file` key.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace voxc::inputs {

// Every size and amount of work an input may ask for; checked before the work it bounds.
struct Limits {
    int64_t maxPixels = int64_t(4096) * 4096;   // a height image's width x height
    int64_t maxTriangles = 2'000'000;           // a mesh's, after polygons are split
    int64_t maxPoints = 2'000'000;              // a mesh's vertices
    int64_t maxDistanceCells = int64_t(256) * 256 * 256; // a mesh's signed-distance grid
};

// Why an input cannot be used. `code`: E0012 for a limit, E0102 for a file that is not what its
// format says (truncated, inconsistent, non-finite values), E0010 for a valid file of a kind voxc
// does not take (an RGB image, a tiled TIFF, a glTF with external buffers).
struct InputError : std::runtime_error {
    std::string code;
    InputError(std::string code, const std::string& message) : std::runtime_error(message), code(std::move(code)) {}
};

// The file is not what its format says (E0102).
[[noreturn]] inline void malformed(const std::string& message) { throw InputError("E0102", message); }

} // namespace voxc::inputs

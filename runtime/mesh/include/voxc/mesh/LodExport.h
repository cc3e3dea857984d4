#pragma once
// LOD meshes as files, the way `voxc run --lod` writes them (docs/cli.md): one whole mesh per level
// beside the -o path ("x.glb" -> "x.lod0.glb", "x.lod1.glb", ...), the LOD chain a game engine
// swaps by distance (Godot's visibility ranges, Unity's LOD Group), and optionally one mesh of
// mixed levels around a point with transition cells where levels meet (voxc/mesh/Lod.h), written
// to the -o path itself. Every mesh is checked by the independent MeshQuality before it is added
// to the caller's set: closed, manifold and oriented, else an InternalError (a crack is a bug).
#include "voxc/core/AtomicWrite.h"
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace voxc {

struct LodExportRequest {
    std::vector<int> levels;                 // each 0..kMaxLodLevel, 2^level <= the grid's chunk size
    std::optional<glm::vec3> layoutCentre;   // also write the mixed-level mesh around this world point
    float iso = 0.5f;
};

// "dir/x.glb", 2 -> "dir/x.lod2.glb" (the extension kept, any case).
std::string lodMeshPath(const std::string& meshPath, int level);

// Meshes and adds the files to `outputs`; returns the report, one line per file. UserError for a
// level out of range or too wide for the chunks (naming --lod).
std::string writeLodMeshes(OutputFiles& outputs, const ChunkedGrid& grid, const LodExportRequest& request,
                           const std::string& meshPath, std::span<const Material> materials);

} // namespace voxc

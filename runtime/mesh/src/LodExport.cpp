// LOD meshes as files (voxc/mesh/LodExport.h).
#include "voxc/mesh/LodExport.h"

#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/Lod.h"
#include "voxc/mesh/MeshQuality.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>

namespace voxc {

std::string lodMeshPath(const std::string& meshPath, int level) {
    const std::filesystem::path path(meshPath);
    std::filesystem::path named = path;
    named.replace_filename(fmt::format("{}.lod{}{}", path.stem().string(), level, path.extension().string()));
    return named.string();
}

namespace {

std::string checkedReport(const std::string& path, const Mesh& mesh, const std::string& what) {
    const MeshQuality quality = measureMeshQuality(mesh);
    if (!quality.manifold() || quality.nonFiniteVertices != 0)
        throw InternalError("the " + what + " mesh is broken: " + describeMeshQuality(quality));
    return fmt::format("wrote {} ({}): {}; watertight\n", path, what, describeMeshQuality(quality));
}

} // namespace

std::string writeLodMeshes(OutputFiles& outputs, const ChunkedGrid& grid, const LodExportRequest& request,
                           const std::string& meshPath, std::span<const Material> materials) {
    const int chunkSize = grid.layout().chunkSize;
    for (int level : request.levels) {
        if (level < 0 || level > kMaxLodLevel) throw UserError(fmt::format("--lod {}: levels run from 0 to {}", level, kMaxLodLevel));
        if ((1 << level) > chunkSize)
            throw UserError(fmt::format("--lod {}: level {} cells are {} voxels wide, wider than the world's {}-voxel chunks", level,
                                        level, 1 << level, chunkSize));
    }
    const int maxLevel = *std::max_element(request.levels.begin(), request.levels.end());
    const LodPyramid pyramid(grid, maxLevel);
    const MeshOptions options{.iso = request.iso};
    std::string report;
    for (int level : request.levels) {
        const std::string path = lodMeshPath(meshPath, level);
        const Mesh mesh = meshLod(pyramid, LodLayout::uniform(grid.layout(), level), options);
        report += checkedReport(path, mesh, fmt::format("marching cubes, LOD {}, cells {} voxel{} wide", level, 1 << level, level ? "s" : ""));
        writeMesh(outputs, path, mesh, materials);
    }
    if (request.layoutCentre) {
        const glm::vec3 c = *request.layoutCentre;
        const LodLayout layout = LodLayout::aroundPoint(grid.layout(), c, maxLevel);
        LodStats stats;
        const Mesh mesh = meshLod(pyramid, layout, options, &stats);
        std::string levels;
        for (int k = 0; k <= maxLevel; ++k) levels += fmt::format("{}{} at LOD {}", k ? ", " : "", stats.chunksPerLevel[size_t(k)], k);
        report += checkedReport(meshPath, mesh,
                                fmt::format("marching cubes, LOD by distance from ({}, {}, {}): chunks {}; {} transition faces, "
                                            "{} transition cells",
                                            c.x, c.y, c.z, levels, stats.transitionFaces, stats.transitionCells));
        writeMesh(outputs, meshPath, mesh, materials);
    }
    return report;
}

} // namespace voxc

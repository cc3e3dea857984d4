#include "voxc/viewer/Preview.h"

#include "voxc/codegen/CompileCache.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/generators/terrain/Block.h"
#include "voxc/stages/Solve.h"
#include "voxc/stages/SolveCache.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxc::viewer {

namespace {

glm::ivec3 floorDiv(glm::ivec3 v, int32_t f) {
    return glm::ivec3(glm::floor(glm::dvec3(v) / double(f)));
}

// The least power of two that brings the block's box to at most `cells` cells; 1 when it is there.
int32_t coarseFactor(const CurvesBlock& block, uint64_t cells) {
    int32_t f = 1;
    const auto count = [&](int32_t factor) {
        const glm::ivec3 size = floorDiv(block.min + block.size - 1, factor) - floorDiv(block.min, factor) + 1;
        return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z);
    };
    while (count(f) > cells && f < 64) f *= 2;
    return f;
}

bool cached(const CurvesBlock& block) {
    const std::optional<std::filesystem::path> directory = codegen::compileCacheDirectory();
    return directory && stages::hasSolve(*directory, stages::solveKey(block, false));
}

bool previewed(const CurvesBlock& block, const PreviewOptions& options) {
    if (block.table || options.curvesCells == 0) return false;
    if (block.scene) return coarseFactor(block, options.curvesCells) > 1 && !cached(block);
    if (block.terrain) return block.terrain->map.domain.maxLevel > options.terrainLevel && !cached(block);
    return false;
}

// The scene on a box coarser by f: coarse voxel q is grid-local voxel f * q, so every position is
// divided by f (the noise frequency multiplied, so the displacement samples the same noise), and
// every length in voxels too, except that a bitangent keeps at least one voxel (the voxeliser
// refuses ribbons narrower than half of one).
curves::Scene coarseScene(const curves::Scene& scene, int32_t f) {
    const double s = 1.0 / f;
    curves::Scene coarse;
    coarse.box.min = floorDiv(scene.box.min, f);
    coarse.box.size = floorDiv(scene.box.min + scene.box.size - 1, f) - coarse.box.min + 1;
    coarse.options = scene.options;
    if (coarse.options.sweeps > 0) coarse.options.sweeps = std::max(1u, coarse.options.sweeps / uint32_t(f));
    coarse.noiseFrequency = scene.noiseFrequency * float(f);
    coarse.noiseSeed = scene.noiseSeed;
    const auto shorter = [&](std::optional<glm::dvec3>& b) {
        if (b) *b = *b * std::max(s, 1.0 / std::max(1.0, glm::length(*b)));
    };
    for (curves::FeatureCurve curve : scene.curves) {
        for (glm::dvec3& p : curve.points) p *= s;
        for (curves::ConstraintPoint& c : curve.constraints) {
            shorter(c.left);
            shorter(c.right);
            c.amplitude *= s;
        }
        coarse.curves.push_back(std::move(curve));
    }
    // Inputs are box-local: fine local l is grid-local l + min, coarse local (l + min) / f - coarse min.
    const glm::dvec3 fineMin(scene.box.min), coarseMin(coarse.box.min);
    const auto toCoarse = [&](glm::dvec3 local) { return (local + fineMin) * s - coarseMin; };
    for (const std::shared_ptr<const curves::InputSurface>& input : scene.inputs) {
        auto surface = std::make_shared<curves::InputSurface>(*input);
        for (auto& triangle : surface->triangles)
            for (glm::dvec3& v : triangle) v = toCoarse(v);
        if (!input->heights.empty()) {
            // Columns -1 .. size of the box, x fastest: each coarse column takes the fine column
            // under it (clamped to the fine ones).
            const glm::ivec3 fine = scene.box.size, size = coarse.box.size;
            surface->heights.assign(size_t(size.x + 2) * size_t(size.z + 2), 0.0);
            for (int32_t z = -1; z <= size.z; ++z)
                for (int32_t x = -1; x <= size.x; ++x) {
                    const int32_t fx = std::clamp((x + coarse.box.min.x) * f - scene.box.min.x, -1, fine.x);
                    const int32_t fz = std::clamp((z + coarse.box.min.z) * f - scene.box.min.z, -1, fine.z);
                    const double h = input->heights[size_t(fz + 1) * size_t(fine.x + 2) + size_t(fx + 1)];
                    surface->heights[size_t(z + 1) * size_t(size.x + 2) + size_t(x + 1)] = toCoarse({0, h, 0}).y;
                }
        }
        coarse.inputs.push_back(std::move(surface));
    }
    coarse.inputOptions = scene.inputOptions;
    coarse.inputOptions.deadZone = int32_t(std::ceil(scene.inputOptions.deadZone * s));
    coarse.inputOptions.amplitude *= s;
    return coarse; // constraints null: solveScene voxelises the coarse curves
}

// The coarse table over the fine box: densities interpolated trilinearly between coarse cells and
// steepened back to the fine ramp (a coarse density d is 0.5 - S/2 in coarse voxels, S * f in fine
// ones, so 0.5 + f * (d - 0.5)); a solid cell takes the material of its densest coarse corner.
SolveTable upsampled(const SolveTable& coarse, const curves::Box& fine, int32_t f) {
    SolveTable table;
    table.min = fine.min;
    table.size = fine.size;
    table.source = coarse.source;
    table.solves = coarse.solves;
    table.notes = fmt::format("a preview solved on a box {} times coarser", f);
    table.density.resize(table.cellCount());
    if (!coarse.material.empty()) table.material.resize(table.cellCount());
    const glm::ivec3 last = coarse.size - 1;
    const auto at = [&](glm::ivec3 c) {
        return (size_t(c.z) * size_t(coarse.size.y) + size_t(c.y)) * size_t(coarse.size.x) + size_t(c.x);
    };
    size_t out = 0;
    for (int32_t z = 0; z < fine.size.z; ++z)
        for (int32_t y = 0; y < fine.size.y; ++y)
            for (int32_t x = 0; x < fine.size.x; ++x, ++out) {
                const glm::dvec3 c = glm::dvec3(fine.min + glm::ivec3(x, y, z)) / double(f) - glm::dvec3(coarse.min);
                const glm::dvec3 clamped = glm::clamp(c, glm::dvec3(0.0), glm::dvec3(last));
                const glm::ivec3 i0 = glm::ivec3(glm::floor(clamped));
                const glm::ivec3 i1 = glm::min(i0 + 1, last);
                const glm::dvec3 t = clamped - glm::dvec3(i0);
                double d = 0.0;
                size_t densest = at(i0);
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::ivec3 pick((corner & 1) ? i1.x : i0.x, (corner & 2) ? i1.y : i0.y, (corner & 4) ? i1.z : i0.z);
                    const double w = ((corner & 1) ? t.x : 1 - t.x) * ((corner & 2) ? t.y : 1 - t.y) * ((corner & 4) ? t.z : 1 - t.z);
                    d += w * coarse.density[at(pick)];
                    if (coarse.density[at(pick)] > coarse.density[densest]) densest = at(pick);
                }
                const float density = float(std::clamp(0.5 + f * (d - 0.5), 0.0, 1.0));
                table.density[out] = density;
                // A solid fine cell has a solid corner (the interpolation of corners all below 0.5
                // is below it), and the densest corner is one: its material.
                if (!table.material.empty() && density >= 0.5f) table.material[out] = coarse.material[densest];
            }
    return table;
}

// A terrain to `level` at most: its splines clamped to the levels it has, erosion on those only.
terrain::TerrainBlock coarseTerrain(const terrain::TerrainBlock& block, int32_t level) {
    terrain::TerrainBlock coarse = block;
    terrain::Domain& domain = coarse.map.domain;
    domain.maxLevel = std::min(domain.maxLevel, level);
    domain.minLevel = std::min(domain.minLevel, domain.maxLevel);
    for (terrain::Spline& spline : coarse.map.splines) {
        spline.minLevel = std::min(spline.minLevel, domain.maxLevel);
        spline.maxLevel = std::min(spline.maxLevel, domain.maxLevel);
    }
    if (coarse.erosion) std::erase_if(coarse.erosion->levelSteps, [&](const auto& entry) { return entry.first > domain.maxLevel; });
    return coarse;
}

} // namespace

bool needsPreview(const Program& program, const PreviewOptions& options) {
    return std::any_of(program.curves.begin(), program.curves.end(),
                       [&](const CurvesBlock& block) { return previewed(block, options); });
}

std::vector<std::string> solveKeys(const Program& program) {
    std::vector<std::string> keys;
    for (const CurvesBlock& block : program.curves)
        if (!block.table && (block.scene || block.terrain)) keys.push_back(stages::solveKey(block, false));
    return keys;
}

Program previewProgram(const Program& program, const PreviewOptions& options) {
    Program preview = program;
    for (CurvesBlock& block : preview.curves) {
        if (!previewed(block, options)) continue;
        SolveTable table;
        if (block.scene) {
            const int32_t f = coarseFactor(block, options.curvesCells);
            table = upsampled(curves::solveScene(coarseScene(*block.scene, f), curves::Limits{}), block.scene->box, f);
        } else {
            const terrain::TerrainBlock coarse = coarseTerrain(*block.terrain, options.terrainLevel);
            table = terrain::solveTerrain(coarse).table;
            stages::replaceTerrainMap(preview, block.name, terrain::solvedMap(coarse, *table.terrainMaps));
            table.notes = fmt::format("a preview to level {}", coarse.map.domain.maxLevel);
        }
        stages::keepTable(preview.world, block, std::move(table));
    }
    stages::solveBlocks(preview); // the small and the cached blocks, as a run solves them
    return preview;
}

} // namespace voxc::viewer

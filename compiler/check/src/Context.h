#pragma once
// State shared by the checker's passes over one file.
#include "Constants.h"
#include "Materials.h"

#include "voxc/generators/inputs/MeshFile.h"
#include "voxc/program/Program.h"
#include "voxc/syntax/Diagnostics.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace voxc::check {

struct Context {
    Diagnostics& diagnostics;
    const Limits& limits;
    Constants constants;
    MaterialNames materials; // filled by checkMaterials before any other block is checked
    std::vector<std::string> curvesNames{}; // the solve blocks (curves, then terrain), declaration order, for the pipeline
    std::vector<std::string> curvesKinds{}; // per solve block: "curves" or "terrain", for messages
    // Each terrain and heightmap block's height map, which fields sample as NAME(wx, wz), and each
    // mesh block's signed distances, NAME(wp); a terrain's as declared (its heights come with the
    // run's solve, stages::solveBlocks); null for a block with errors (reported), so its uses
    // report nothing more.
    std::map<std::string, std::shared_ptr<const SampledMap>, std::less<>> maps{};
    // Each mesh block's triangles placed in world voxels, for the curves blocks that take it as
    // an input (docs/curves.md, "Heightmaps and meshes as inputs").
    std::map<std::string, std::shared_ptr<const inputs::TriangleMesh>, std::less<>> placedMeshes{};
    // List entries of the lsystem_cave point sets checked so far: the runtime bounds their sum.
    uint64_t pointSetListEntries = 0;
    std::optional<uint32_t> seed{}; // CheckOptions::seed
    std::optional<std::pair<glm::ivec3, glm::ivec3>> region{}; // CheckOptions::region
    std::function<std::optional<std::string>(const std::string&)> readRuleFile{}; // CheckOptions::readRuleFile
    std::function<std::optional<std::string>(const std::string&)> readInputFile{}; // CheckOptions::readInputFile
    // W0209 of an lsystem_cave whose carve reaches none of the grid: given once the pipeline is
    // known, and not for a feature only stamps use (a stamp carves around its anchor instead).
    struct CarveWarning {
        std::string feature;
        SourceLoc loc;
        std::string message;
    };
    std::vector<CarveWarning> carveWarnings{};
};

} // namespace voxc::check

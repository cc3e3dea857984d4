#pragma once
// `heightmap NAME { file = "ridge.png"; ... }` and `mesh NAME { file = "boulder.glb"; ... }`
// (docs/language.md, "Heightmaps", "Meshes"): files made by other tools as modelling primitives.
// The file is read when the file is checked (relative to the .vox's folder; CheckOptions'
// readInputFile serves a package's copies), decoded by voxc_generators' inputs/ (height images;
// meshes turned into signed distances with OpenVDB) and kept as a SampledMap that fields sample,
// NAME(wx, wz) for a heightmap and NAME(wp) for a mesh, like a terrain block's map. Every error
// about the file is located at the block's `file` value.
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <string>
#include <vector>

namespace voxc::check {

// Every heightmap and mesh block in declaration order: their maps go into context.maps (null for
// a block with errors), the files they read are returned.
std::vector<InputFile> checkInputs(Context& context, const ast::File& file, const std::string& sourcePath);

} // namespace voxc::check

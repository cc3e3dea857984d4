#pragma once
// `terrain NAME { size; levels; max_height; preset; noise { ... }; spline NAME { ... } ... }`
// (docs/language.md, "Terrain"; docs/terrain.md): a Mathisen heightfield (diffusion cascade of
// feature splines, then pipe-model erosion) generated when the program runs (stages::solveBlocks)
// and voxelised into a solve table over the grid, used in the pipeline like a curves block, by
// name with a mode (`set valley;`).
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <vector>

namespace voxc::check {

// Every terrain block, in declaration order, with its checked TerrainBlock (CurvesBlock::terrain);
// a block with errors (reported) has none.
// `usedNames`: the names of every other stage, which a terrain block may not take.
std::vector<CurvesBlock> checkTerrains(Context& context, const ast::File& file, const World& world,
                                       const std::vector<std::string>& usedNames);

} // namespace voxc::check

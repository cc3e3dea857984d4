#pragma once
// `curves NAME { box = ...; curve NAME { points = ...; constraint { t = 0; ... } ... } ... }`
// (docs/language.md, "Curves"; docs/curves.md): feature curves voxelised when the file is checked
// and solved when it runs (stages::solveBlocks), used as a pipeline stage by name with a mode
// (`union cliffs;`).
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <vector>

namespace voxc::check {

// Every curves block, in declaration order, with its scene; a block with errors (reported) has none.
// Names share the namespace of grammars, fields and features (`stageNames`).
std::vector<CurvesBlock> checkCurves(Context& context, const ast::File& file, const World& world,
                                     const std::vector<std::string>& stageNames);

} // namespace voxc::check

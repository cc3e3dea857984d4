#pragma once
// `curves NAME { box = ...; curve NAME { points = ...; constraint { t = 0; ... } ... } ... }`
// (docs/language.md, "Curves"; docs/curves.md): feature curves solved on the host when the file
// is checked, used as a pipeline stage by name with a mode (`union cliffs;`).
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <vector>

namespace voxc::check {

// Every curves block, in declaration order; a block with errors (reported) has no table.
// Names share the namespace of grammars, fields and features (`stageNames`).
std::vector<CurvesBlock> checkCurves(Context& context, const ast::File& file, const World& world,
                                     const std::vector<std::string>& stageNames);

} // namespace voxc::check

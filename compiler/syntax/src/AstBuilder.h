#pragma once
// Converts ANTLR's parse tree into the immutable ast::File. Tolerates the holes error
// recovery leaves (missing children), since a tree with syntax errors is still built.
#include "voxc/syntax/Ast.h"

#include "VoxcParser.h"

namespace voxc {

ast::File buildAst(grammar::VoxcParser::FileContext& file);

} // namespace voxc

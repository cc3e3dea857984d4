#pragma once
// Symbols and transforms are written as rows, first row = top (highest y), columns along +x,
// and `layer { ... }` blocks from lowest z. This converts the printed form into Program's
// cell order (cellIndex: x fastest, then y, then z) and converts each cell's operators.
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <optional>
#include <vector>

namespace voxc::check {

// The cells of a `symbol` or `transform` block, indexed by cellIndex(size, x, y, z).
// Reports ragged rows or layers (E0005) and counts that disagree with `size` (E0004).
std::optional<std::vector<const ast::Cell*>> readLayout(Context& context, const ast::Block& block, glm::ivec3 size);

// `GEQ 0.5 & LT 0.9 & MAT rock`: operator names (E0011), arity (E0006), values and material
// names (E0002), at most Limits::maxCellTerms of them (E0012). IGN terms are dropped, since an
// empty predicate list already means IGN.
std::optional<SymbolCell> convertSymbolCell(Context& context, const ast::Cell& cell);

// `ADD -0.5`, `MAT sand` or `SET 1 & MAT sand`: one density operator (NOP when only a material
// is written) and at most one `MAT` (E0003 for a second).
std::optional<TransformCell> convertTransformCell(Context& context, const ast::Cell& cell);

} // namespace voxc::check

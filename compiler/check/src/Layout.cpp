#include "Layout.h"

#include "Suggest.h"
#include "Values.h"

#include "voxc/builtins/Ops.h"

#include <fmt/format.h>

namespace voxc::check {

namespace {

using Layer = std::vector<const ast::Row*>;

std::string plural(size_t n, const char* word) { return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s"); }

// The block's layers: its own rows as one layer, or one per `layer { ... }` block.
std::optional<std::vector<Layer>> collectLayers(Context& context, const ast::Block& block) {
    const std::string where = fmt::format("'{}' block", block.kind);
    checkLabel(context, block, false);
    rejectUnexpectedMembers(context, block, where, {.blocks = true, .rows = true});
    for (const ast::Assignment& a : block.assignments)
        context.diagnostics.error("E0008", a.loc, fmt::format("unexpected key '{}' in {}; it holds rows", a.key, where));
    if (!block.rows.empty() && !block.blocks.empty()) {
        context.diagnostics.error("E0005", block.blocks.front().loc,
                                  fmt::format("{} mixes rows and 'layer' blocks; write either rows (one layer) or "
                                              "only 'layer' blocks",
                                              where));
        return std::nullopt;
    }
    std::vector<Layer> layers;
    if (block.blocks.empty()) {
        layers.emplace_back();
        for (const ast::Row& row : block.rows) layers.back().push_back(&row);
        return layers;
    }
    bool ok = true;
    static constexpr std::string_view kLayer[] = {"layer"};
    for (const ast::Block& layerBlock : block.blocks) {
        if (layerBlock.kind != "layer") {
            context.diagnostics.error("E0008", layerBlock.loc,
                                      fmt::format("unknown block '{}' in {}{}", layerBlock.kind, where,
                                                  didYouMean(layerBlock.kind, kLayer)));
            ok = false;
            continue;
        }
        checkLabel(context, layerBlock, false);
        rejectUnexpectedMembers(context, layerBlock, "'layer' block", {.rows = true});
        for (const ast::Assignment& a : layerBlock.assignments)
            context.diagnostics.error("E0008", a.loc, fmt::format("unexpected key '{}' in 'layer' block", a.key));
        layers.emplace_back();
        for (const ast::Row& row : layerBlock.rows) layers.back().push_back(&row);
    }
    return ok ? std::optional(layers) : std::nullopt;
}

// E0005: every row of every layer has the length of the first row, and every layer the row
// count of the first layer.
bool checkRectangular(Context& context, const ast::Block& block, const std::vector<Layer>& layers) {
    bool ok = true;
    const ast::Row* firstRow = nullptr;
    for (const Layer& layer : layers)
        if (!firstRow && !layer.empty()) firstRow = layer.front();
    for (size_t k = 0; k < layers.size(); ++k) {
        const Layer& layer = layers[k];
        for (const ast::Row* row : layer) {
            if (row->cells.size() == firstRow->cells.size()) continue;
            context.diagnostics.error("E0005", row->loc,
                                      fmt::format("ragged rows: this row has {} but the first row{} has {}",
                                                  plural(row->cells.size(), "cell"),
                                                  layers.size() > 1 ? " of the first layer" : "",
                                                  plural(firstRow->cells.size(), "cell")),
                                      {{firstRow->loc, "first row"}});
            ok = false;
            break;
        }
        if (layer.size() != layers.front().size()) {
            context.diagnostics.error("E0005", block.blocks[k].loc,
                                      fmt::format("ragged layers: layer {} has {} but layer 1 has {}", k + 1,
                                                  plural(layer.size(), "row"), plural(layers.front().size(), "row")));
            ok = false;
        }
    }
    return ok;
}

// E0004: layer, row and column counts against size = [I, J, K].
bool checkCounts(Context& context, const ast::Block& block, const std::vector<Layer>& layers, glm::ivec3 size) {
    const std::string declared = formatVec(size);
    if (int(layers.size()) != size.z) {
        context.diagnostics.error("E0004", block.loc,
                                  fmt::format("{} has {} but size {} declares {}{}", block.kind,
                                              plural(layers.size(), "layer"), declared, size.z,
                                              block.blocks.empty() ? "; write one 'layer { ... }' per z slice" : ""));
        return false;
    }
    const Layer& first = layers.front();
    if (int(first.size()) != size.y) {
        context.diagnostics.error("E0004", block.loc,
                                  fmt::format("{} has {}{} but size {} declares {}", block.kind,
                                              plural(first.size(), "row"), layers.size() > 1 ? " per layer" : "",
                                              declared, size.y));
        return false;
    }
    if (int(first.front()->cells.size()) != size.x) {
        context.diagnostics.error("E0004", first.front()->loc,
                                  fmt::format("{} rows have {} but size {} declares {}", block.kind,
                                              plural(first.front()->cells.size(), "column"), declared, size.x));
        return false;
    }
    return true;
}

} // namespace

std::optional<std::vector<const ast::Cell*>> readLayout(Context& context, const ast::Block& block, glm::ivec3 size) {
    auto layers = collectLayers(context, block);
    if (!layers || !checkRectangular(context, block, *layers) || !checkCounts(context, block, *layers, size))
        return std::nullopt;
    std::vector<const ast::Cell*> cells(size_t(size.x) * size.y * size.z, nullptr);
    for (int z = 0; z < size.z; ++z)
        for (int row = 0; row < size.y; ++row)
            for (int x = 0; x < size.x; ++x) {
                const int y = size.y - 1 - row; // the first printed row is the top
                cells[cellIndex(size, x, y, z)] = &(*layers)[z][row]->cells[x];
            }
    return cells;
}

namespace {

// E0006: a value where the operator takes none, or none where it needs one.
bool checkArity(Context& context, const ast::Term& term, bool takesValue) {
    if (takesValue && !term.value) {
        context.diagnostics.error("E0006", term.opLoc, fmt::format("'{}' needs a value, as in '{} 0.5'", term.op, term.op));
        return false;
    }
    if (!takesValue && term.value) {
        context.diagnostics.error("E0006", term.value->loc, fmt::format("'{}' takes no value", term.op));
        return false;
    }
    return true;
}

std::vector<std::string_view> opNames(bool symbol) {
    std::vector<std::string_view> names;
    if (symbol) {
        for (const SymbolOpInfo& info : symbolOps()) names.push_back(info.name);
        for (const MaterialOpInfo& info : materialOps()) names.push_back(info.name);
    } else {
        for (const TransformOpInfo& info : transformOps()) names.push_back(info.name);
        names.push_back(materialOpInfo(MaterialOp::MAT).name);
    }
    return names;
}

void reportUnknownOp(Context& context, const ast::Term& term, bool symbol) {
    const char* kind = symbol ? "symbol" : "transform";
    bool otherKind = symbol ? findTransformOp(term.op).has_value() : findSymbolOp(term.op).has_value();
    if (otherKind) {
        context.diagnostics.error("E0011", term.opLoc,
                                  fmt::format("'{}' is a {} operator and cannot appear in a {}", term.op,
                                              symbol ? "transform" : "symbol", kind));
        return;
    }
    context.diagnostics.error("E0011", term.opLoc,
                              fmt::format("unknown {} operator '{}'{}", kind, term.op,
                                          suggestOrList(term.op, opNames(symbol))));
}

// `MAT rock`: the operand is a material name (E0006 when missing).
std::optional<uint8_t> readMaterialOperand(Context& context, const ast::Term& term) {
    if (!term.value) {
        context.diagnostics.error("E0006", term.opLoc,
                                  fmt::format("'{}' needs a material name, as in '{} rock'", term.op, term.op));
        return std::nullopt;
    }
    return context.materials.resolve(context.diagnostics, *term.value, fmt::format("'{}'", term.op));
}

} // namespace

std::optional<SymbolCell> convertSymbolCell(Context& context, const ast::Cell& cell) {
    // Every test of every cell is compiled into the sweep's kernel and run at every anchor.
    if (cell.terms.size() > size_t(context.limits.maxCellTerms)) {
        context.diagnostics.error("E0012", cell.loc,
                                  fmt::format("this cell joins {} tests with '&', more than the limit of {}",
                                              cell.terms.size(), context.limits.maxCellTerms));
        return std::nullopt;
    }
    SymbolCell out;
    bool ok = true;
    for (const ast::Term& term : cell.terms) {
        if (std::optional<MaterialOp> materialOp = findMaterialOp(term.op)) {
            auto material = readMaterialOperand(context, term);
            if (material)
                out.materialPredicates.push_back({*materialOp, *material});
            else
                ok = false;
            continue;
        }
        std::optional<SymbolOp> op = findSymbolOp(term.op);
        if (!op) {
            reportUnknownOp(context, term, true);
            ok = false;
            continue;
        }
        const SymbolOpInfo& info = symbolOpInfo(*op);
        if (!checkArity(context, term, info.takesValue)) {
            ok = false;
            continue;
        }
        Predicate predicate{*op, 0.0f};
        if (term.value) {
            auto value = readFloat(context, *term.value);
            if (!value) {
                ok = false;
                continue;
            }
            predicate.value = *value;
        }
        if (*op != SymbolOp::IGN) out.predicates.push_back(predicate);
    }
    return ok ? std::optional(out) : std::nullopt;
}

std::optional<TransformCell> convertTransformCell(Context& context, const ast::Cell& cell) {
    // One density operator and at most one `MAT m`, in either order; `MAT m` alone keeps the density.
    const ast::Term* densityTerm = nullptr;
    const ast::Term* materialTerm = nullptr;
    for (const ast::Term& term : cell.terms) {
        if (term.op == materialOpInfo(MaterialOp::MAT).name) {
            if (materialTerm) {
                context.diagnostics.error("E0003", term.opLoc, "a transform cell writes one material; this is a second 'MAT'",
                                          {{materialTerm->opLoc, "the first 'MAT' is here"}});
                return std::nullopt;
            }
            materialTerm = &term;
            continue;
        }
        if (findMaterialOp(term.op)) {
            context.diagnostics.error("E0011", term.opLoc,
                                      fmt::format("'{}' is a symbol test and cannot appear in a transform; 'MAT' "
                                                  "writes a material",
                                                  term.op));
            return std::nullopt;
        }
        if (densityTerm) {
            context.diagnostics.error("E0006", term.opLoc,
                                      "a transform cell takes one density operator; '&' joins it only with 'MAT NAME'");
            return std::nullopt;
        }
        densityTerm = &term;
    }
    TransformCell out{TransformOp::NOP, 0.0f, std::nullopt};
    if (densityTerm) {
        std::optional<TransformOp> op = findTransformOp(densityTerm->op);
        if (!op) {
            reportUnknownOp(context, *densityTerm, false);
            return std::nullopt;
        }
        if (!checkArity(context, *densityTerm, transformOpInfo(*op).takesValue)) return std::nullopt;
        out.op = *op;
        if (densityTerm->value) {
            auto value = readFloat(context, *densityTerm->value);
            if (!value) return std::nullopt;
            out.value = *value;
        }
    }
    if (materialTerm) {
        auto material = readMaterialOperand(context, *materialTerm);
        if (!material) return std::nullopt;
        out.material = *material;
    }
    return out;
}

} // namespace voxc::check

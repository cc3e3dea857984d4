#include "CheckStamps.h"

#include "Suggest.h"
#include "Values.h"

#include "voxc/program/Semantics.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::check {

namespace {

constexpr std::string_view kModeNames[] = {"union", "subtract", "set", "intersect"};
constexpr FieldMode kModes[] = {FieldMode::Union, FieldMode::Subtract, FieldMode::Set, FieldMode::Intersect};

// A bare name as a key's value (E0010 otherwise).
const ast::Expr* nameValue(Context& context, const ast::Assignment& a, std::string_view example) {
    if (!a.value.isList() && a.value.scalar->kind == ast::Expr::Kind::Name) return a.value.scalar.get();
    context.diagnostics.error("E0010", a.value.loc, fmt::format("'{}' expects a name, as in '{}'", a.key, example));
    return nullptr;
}

// `reach = 4;` or `reach = [2, 12, 2];`: whole voxels, each at most Limits::maxStampReach (E0012).
std::optional<glm::ivec3> readReach(Context& context, const ast::Assignment& a) {
    std::optional<glm::ivec3> reach;
    if (a.value.isList()) {
        reach = readIntegerVec3(context, a, 0, int64_t(1) << 30);
    } else if (auto one = readInteger(context, a, 0, int64_t(1) << 30)) {
        reach = glm::ivec3(int32_t(*one));
    }
    if (!reach) return std::nullopt;
    const int32_t most = std::max({reach->x, reach->y, reach->z});
    if (most > context.limits.maxStampReach) {
        context.diagnostics.error("E0012", a.value.loc,
                                  fmt::format("a stamp reaches {} voxels beyond its window, more than the limit of {}",
                                              most, context.limits.maxStampReach));
        return std::nullopt;
    }
    return reach;
}

bool readsPointSet(const Field& field) {
    return std::any_of(field.nodes.begin(), field.nodes.end(),
                       [](const FieldNode& node) { return node.kind == FieldNode::Kind::PointSet; });
}

} // namespace

std::optional<Stamp> checkStampBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                     const std::string& rule, SourceLoc& reachLoc) {
    static constexpr std::string_view kKeys[] = {"mode", "offset", "reach", "material"};
    const std::string where = fmt::format("'stamp' of {}", rule);
    if (!checkLabel(context, block, true)) return std::nullopt;
    rejectUnexpectedMembers(context, block, where, {});
    BlockKeys keys(context, block, where, kKeys);
    const int errorsBefore = context.diagnostics.errorCount();

    Stamp stamp;
    stamp.writtenSize = windowSize;
    stamp.fieldName = *block.label;
    stamp.loc = block.labelLoc;
    if (const ast::Assignment* a = keys.find("mode"))
        if (const ast::Expr* name = nameValue(context, *a, "subtract")) {
            const auto it = std::find(std::begin(kModeNames), std::end(kModeNames), name->name);
            if (it == std::end(kModeNames))
                context.diagnostics.error("E0011", name->loc,
                                          fmt::format("unknown stamp mode '{}'{}", name->name,
                                                      suggestOrList(name->name, kModeNames)));
            else
                stamp.mode = kModes[it - std::begin(kModeNames)];
        }
    if (const ast::Assignment* a = keys.find("offset"))
        if (auto offset = readNumberVec3(context, *a, -1e6, 1e6))
            stamp.offset = glm::vec3(float((*offset)[0]), float((*offset)[1]), float((*offset)[2]));
    if (const ast::Assignment* a = keys.require("reach")) {
        reachLoc = a->value.loc;
        if (auto reach = readReach(context, *a)) stamp.reach = *reach;
    }
    if (const ast::Assignment* a = keys.find("material")) stamp.material = readMaterialKey(context, *a);

    if (context.diagnostics.errorCount() != errorsBefore) return std::nullopt;
    return stamp;
}

void checkStampOverlap(Context& context, const Grammar& grammar, const std::vector<RuleSyntax>& rules) {
    for (const Sweep& sweep : orderSweeps(grammar)) {
        for (uint32_t r : sweep.rules) {
            const Rule& rule = grammar.rules[r];
            for (size_t s = 0; s < rule.stamps.size(); ++s) {
                int64_t overlap = 1;
                for (int axis = 0; axis < 3; ++axis) {
                    const int64_t spacing = int64_t(sweep.phaseCount[axis]) * grammar.stride[axis];
                    const int64_t grown = int64_t(sweep.window[axis]) + 2 * int64_t(rule.stamps[s].reach[axis]);
                    const int64_t anchors = (int64_t(sweep.anchorCount[axis]) + sweep.phaseCount[axis] - 1) /
                                            sweep.phaseCount[axis]; // of one phase, at most
                    overlap *= std::min((grown + spacing - 1) / spacing, std::max<int64_t>(anchors, 1));
                }
                if (overlap <= context.limits.maxStampOverlap) continue;
                context.diagnostics.error(
                    "E0012", rules[r].stampReachLocs.at(s),
                    fmt::format("rule '{}': its stamp's grown windows of one phase cover a voxel up to {} times, more "
                                "than the limit of {}; a smaller reach or a larger grammar stride spaces them out",
                                rule.name, overlap, context.limits.maxStampOverlap));
                return;
            }
        }
    }
}

void resolveStampFields(Context& context, std::vector<Grammar>& grammars, const std::vector<Field>& fields) {
    std::vector<std::string_view> names;
    for (const Field& field : fields) names.push_back(field.name);
    for (Grammar& grammar : grammars)
        for (Rule& rule : grammar.rules)
            for (Stamp& stamp : rule.stamps) {
                const auto it = std::find(names.begin(), names.end(), stamp.fieldName);
                // A variant repeats its rule's stamp: report once, at the written rule.
                const bool variant = rule.name.find('@') != std::string::npos;
                if (it == names.end()) {
                    if (!variant)
                        context.diagnostics.error("E0002", stamp.loc,
                                                  fmt::format("unknown field '{}' in a stamp{}", stamp.fieldName,
                                                              didYouMean(stamp.fieldName, names)));
                    continue;
                }
                stamp.field = uint32_t(it - names.begin());
                if (readsPointSet(fields[stamp.field]) && !variant)
                    context.diagnostics.error("E0013", stamp.loc,
                                              fmt::format("'{}' carves an lsystem's point set, which is binned in grid "
                                                          "coordinates; a stamp cannot move it",
                                                          stamp.fieldName));
            }
}

} // namespace voxc::check

#include "CheckStamps.h"

#include "Suggest.h"
#include "Values.h"

#include "voxc/program/Semantics.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <map>
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

int64_t floorDivide(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

std::string vecText(glm::ivec3 v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

// The positions a stamp's field reads, per written axis: (v - anchor) in the written rule's axes
// minus the offset for every v of the grown window, [-reach, size + reach - 1] - offset (whole
// offsets). The reach is the written rule's, whichever variant `stamp` is.
glm::ivec3 writtenReach(const Stamp& stamp) {
    glm::ivec3 reach(0);
    for (int axis = 0; axis < 3; ++axis) reach[stamp.from[axis]] = stamp.reach[axis];
    return reach;
}

// The copy of `carve` (a field reading one point set from the stamp's frame) that `stamp` reads:
// its point set with lists binned over the stamp's frame box. Nothing, with a located error, when
// the offset is not whole, the carve reaches past the grown window, or the lists pass their limits.
std::optional<Field> framedCarve(Context& context, const Field& carve, const Stamp& stamp, const std::string& rule,
                                 SourceLoc reachLoc, SourceLoc offsetLoc) {
    if (stamp.offset != glm::floor(stamp.offset)) {
        context.diagnostics.error(
            "E0007", offsetLoc,
            fmt::format("'{}' is an lsystem_cave, whose stamp starts its turtle on a voxel: the offset must be whole "
                        "numbers, found [{}, {}, {}]",
                        stamp.fieldName, formatNumber(stamp.offset.x), formatNumber(stamp.offset.y),
                        formatNumber(stamp.offset.z)));
        return std::nullopt;
    }
    const glm::ivec3 offset(stamp.offset), reach = writtenReach(stamp);
    const glm::ivec3 frameLo = -reach - offset, frameHi = stamp.writtenSize + reach - 1 - offset;
    Field out = carve;
    const auto node = std::find_if(out.nodes.begin(), out.nodes.end(),
                                   [](const FieldNode& n) { return n.kind == FieldNode::Kind::PointSet; });
    VOXC_ASSERT(node != out.nodes.end());
    auto framed = std::make_shared<PointSet>(*node->pointSet);

    glm::dvec3 lo, hi;
    if (pointSetSupport(*framed, lo, hi)) {
        // Every voxel the carve can change must lie in the grown window, so no stamp is cut off.
        glm::ivec3 needed(0);
        for (int axis = 0; axis < 3; ++axis)
            needed[axis] = int32_t(std::clamp(std::max(-(std::ceil(lo[axis]) + offset[axis]),
                                                       std::floor(hi[axis]) + offset[axis] - stamp.writtenSize[axis] + 1),
                                              0.0, 1e9));
        if (glm::any(glm::greaterThan(needed, reach))) {
            const bool pastLimit = glm::any(glm::greaterThan(needed, glm::ivec3(context.limits.maxStampReach)));
            context.diagnostics.error(
                "E0012", reachLoc,
                fmt::format("rule '{}': the lsystem_cave '{}' spans [{}, {}, {}] to [{}, {}, {}] in the stamp's frame "
                            "(its skeleton from the frame's origin, with the brush's reach around it), past the window "
                            "grown by reach {}; it needs a reach of at least {}{}",
                            rule, stamp.fieldName, formatNumber(std::ceil(lo.x)), formatNumber(std::ceil(lo.y)),
                            formatNumber(std::ceil(lo.z)), formatNumber(std::floor(hi.x)),
                            formatNumber(std::floor(hi.y)), formatNumber(std::floor(hi.z)), vecText(reach),
                            vecText(needed),
                            pastLimit ? fmt::format(", past the limit of {}: a smaller network (fewer expansions, a "
                                                    "shorter step), a smaller radius or a larger min_scale fits",
                                                    context.limits.maxStampReach)
                                      : ""));
            return std::nullopt;
        }
    }
    glm::ivec3 firstCell, cellCount;
    for (int axis = 0; axis < 3; ++axis) {
        firstCell[axis] = int32_t(floorDivide(frameLo[axis], kPointSetCellSize));
        cellCount[axis] = int32_t(floorDivide(frameHi[axis], kPointSetCellSize) - firstCell[axis] + 1);
    }
    try {
        framed->bins = binPointSet(*framed, firstCell, cellCount, kPointSetCellSize,
                                   kMaxPointSetListEntries - std::min(kMaxPointSetListEntries, context.pointSetListEntries),
                                   kMaxPointSetPerCell);
    } catch (const PointSetLimitError& e) {
        context.diagnostics.error("E0012", reachLoc,
                                  fmt::format("rule '{}': the lists of the lsystem_cave '{}' over the stamp's frame pass "
                                              "the limit '{}' ({} > {})",
                                              rule, stamp.fieldName, e.limit, e.amount, e.cap));
        return std::nullopt;
    }
    context.pointSetListEntries += framed->bins.centreItems.size() + framed->bins.segmentItems.size();
    framed->binnedInFrame = true;
    node->pointSet = std::move(framed);
    return out;
}

} // namespace

std::optional<Stamp> checkStampBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                     const std::string& rule, SourceLoc& reachLoc, SourceLoc& offsetLoc) {
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
    offsetLoc = block.labelLoc;
    if (const ast::Assignment* a = keys.find("offset")) offsetLoc = a->value.loc;
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

void resolveStampFields(Context& context, std::vector<Grammar>& grammars, const std::vector<CheckedGrammar>& syntax,
                        std::vector<Field>& fields, const std::vector<std::optional<Field>>& stampFields) {
    // Copies: `fields` grows below.
    std::vector<std::string> nameCopies;
    for (const Field& field : fields) nameCopies.push_back(field.name);
    const std::vector<std::string_view> names(nameCopies.begin(), nameCopies.end());
    for (size_t g = 0; g < grammars.size(); ++g) {
        // The copy of each declared rule's stamp (declared index, stamp index), for its variants;
        // nothing after an error, which is reported once.
        std::map<std::pair<size_t, size_t>, std::optional<uint32_t>> framedCopies;
        for (size_t r = 0; r < grammars[g].rules.size(); ++r) {
            Rule& rule = grammars[g].rules[r];
            const RuleSyntax& ruleSyntax = syntax.at(g).rules.at(r);
            for (size_t s = 0; s < rule.stamps.size(); ++s) {
                Stamp& stamp = rule.stamps[s];
                const auto it = std::find(names.begin(), names.end(), stamp.fieldName);
                if (it == names.end()) {
                    // A variant repeats its rule's stamp: report once, at the written rule.
                    if (!ruleSyntax.isVariant)
                        context.diagnostics.error("E0002", stamp.loc,
                                                  fmt::format("unknown field '{}' in a stamp{}", stamp.fieldName,
                                                              didYouMean(stamp.fieldName, names)));
                    continue;
                }
                stamp.field = uint32_t(it - names.begin());
                if (stamp.field >= stampFields.size() || !stampFields[stamp.field]) continue;
                const auto [copy, first] = framedCopies.try_emplace({ruleSyntax.declaredIndex, s});
                if (first)
                    if (std::optional<Field> framed = framedCarve(context, *stampFields[stamp.field], stamp, rule.name,
                                                                  ruleSyntax.stampReachLocs.at(s),
                                                                  ruleSyntax.stampOffsetLocs.at(s))) {
                        copy->second = uint32_t(fields.size());
                        fields.push_back(std::move(*framed));
                    }
                if (copy->second) stamp.field = *copy->second;
            }
        }
    }
}

} // namespace voxc::check

// `feature NAME = speleothems { kind = column; spawn_threshold = 0.5; ... material = flowstone; }`
// (docs/language.md, "Speleothems"): the keys read and range-checked with located errors, the
// rules between keys located at the key that breaks them.
#include "Materials.h"
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/generators/WorkErrors.h"
#include "voxc/generators/caves/Speleothems.h"

#include <array>
#include <fmt/format.h>

namespace voxc::check {

namespace {

constexpr std::array<std::string_view, 12> kKeys{"kind",      "cluster_frequency", "cluster_low", "cluster_high",
                                                 "spawn_frequency", "spawn_threshold", "growth", "taper",
                                                 "min_gap",   "max_gap",           "material",    "keep_clear"};
constexpr std::array<std::string_view, 4> kKinds{"stalactite", "stalagmite", "column", "hoodoo"};

const ast::Expr* nameValue(const ast::Assignment& a) {
    const ast::Expr* expr = a.value.isList() ? nullptr : a.value.scalar.get();
    return expr && expr->kind == ast::Expr::Kind::Name ? expr : nullptr;
}

std::optional<SpeleothemKind> readKind(Context& context, const ast::Assignment& a) {
    const ast::Expr* expr = nameValue(a);
    if (expr)
        if (std::optional<SpeleothemKind> kind = caves::findSpeleothemKind(expr->name)) return kind;
    context.diagnostics.error("E0011", a.value.loc,
                              fmt::format("'kind' must be one of {}{}", fmt::join(kKinds, ", "),
                                          expr ? didYouMean(expr->name, kKinds) : std::string()));
    return std::nullopt;
}

// The point set of an lsystem_cave feature declared above (its field's PointSet node).
std::optional<std::shared_ptr<const PointSet>> readKeepClear(Context& context, const ast::Assignment& a,
                                                             const std::vector<Field>& fieldsAbove) {
    const ast::Expr* expr = nameValue(a);
    if (!expr) {
        context.diagnostics.error("E0010", a.value.loc,
                                  "'keep_clear' expects the name of an lsystem_cave feature declared above");
        return std::nullopt;
    }
    std::vector<std::string_view> caves;
    for (const Field& field : fieldsAbove)
        for (const FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::PointSet && node.pointSet) {
                if (field.name == expr->name) return node.pointSet;
                caves.push_back(field.name);
                break;
            }
    context.diagnostics.error("E0002", a.value.loc,
                              fmt::format("'{}' is not an lsystem_cave feature declared above{}", expr->name,
                                          suggestOrList(expr->name, caves)));
    return std::nullopt;
}

template <typename T>
bool readInto(std::optional<T> value, T& out) {
    if (value) out = *value;
    return value.has_value();
}

} // namespace

std::optional<SpeleothemStage> checkSpeleothems(Context& context, const ast::FeatureDecl& decl,
                                                const std::vector<Field>& fieldsAbove) {
    const ast::Block& body = decl.body;
    const std::string where = "'speleothems' feature";
    checkLabel(context, body, false);
    rejectUnexpectedMembers(context, body, where, {});
    BlockKeys keys(context, body, where, kKeys);

    SpeleothemStage out{decl.name, decl.loc, {}, nullptr};
    SpeleothemParams& p = out.params;
    bool ok = true;
    const auto number = [&](std::string_view key, float& field, double lo, double hi) {
        if (const ast::Assignment* a = keys.find(key)) {
            std::optional<double> v = readNumber(context, *a, lo, hi);
            if (v) field = float(*v);
            ok = ok && v.has_value();
        }
    };
    const auto integer = [&](std::string_view key, int32_t& field, int64_t lo, int64_t hi) {
        if (const ast::Assignment* a = keys.find(key)) {
            std::optional<int64_t> v = readInteger(context, *a, lo, hi);
            if (v) field = int32_t(*v);
            ok = ok && v.has_value();
        }
    };
    if (const ast::Assignment* a = keys.find("kind")) ok = readInto(readKind(context, *a), p.kind) && ok;
    number("cluster_frequency", p.clusterFrequency, 0, 1000);
    number("cluster_low", p.clusterLow, -1, 1);
    number("cluster_high", p.clusterHigh, -1, 1);
    number("spawn_frequency", p.spawnFrequency, 0, 1000);
    number("spawn_threshold", p.spawnThreshold, -1, 0.99);
    number("growth", p.growth, 0, 1000);
    integer("taper", p.taper, 0, 8);
    integer("min_gap", p.minGap, 1, 4096);
    integer("max_gap", p.maxGap, 1, 4096);
    if (const ast::Assignment* a = keys.find("material")) {
        p.material = readMaterialKey(context, *a);
        ok = ok && p.material.has_value();
    }
    if (const ast::Assignment* a = keys.find("keep_clear")) {
        std::optional<std::shared_ptr<const PointSet>> set = readKeepClear(context, *a, fieldsAbove);
        if (set) out.clearance = *set;
        ok = ok && set.has_value();
    }
    if (!ok) return std::nullopt;
    // The rules between keys, at the key that breaks them.
    if (p.clusterLow > p.clusterHigh) {
        const ast::Assignment* a = keys.find("cluster_low");
        context.diagnostics.error("E0007", a ? a->value.loc : keys.find("cluster_high")->value.loc,
                                  fmt::format("'cluster_low' ({}) must not be above 'cluster_high' ({})", p.clusterLow,
                                              p.clusterHigh));
        return std::nullopt;
    }
    if (p.minGap > p.maxGap) {
        const ast::Assignment* a = keys.find("max_gap");
        context.diagnostics.error("E0007", a ? a->value.loc : keys.find("min_gap")->value.loc,
                                  fmt::format("'max_gap' ({}) must not be below 'min_gap' ({})", p.maxGap, p.minGap));
        return std::nullopt;
    }
    try {
        caves::checkSpeleothemParams(p); // the same rules, as the generator states them
    } catch (const generators::ParameterError& e) {
        const ast::Assignment* a = keys.find(e.parameter);
        context.diagnostics.error("E0007", a ? a->value.loc : body.loc, e.what());
        return std::nullopt;
    }
    return out;
}

} // namespace voxc::check

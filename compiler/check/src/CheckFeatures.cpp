// `feature name = generator { key = value; ... }`: the keys are read and range-checked against the
// generator's record (voxc_generators, compiler/generators/src/dey) with located diagnostics here;
// the record builds the feature's field from the checked values.
#include "CheckLsystemCave.h"
#include "Materials.h"
#include "Sections.h"
#include "Suggest.h"
#include "Values.h"

#include "voxc/generators/dey/Generators.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace voxc::check {

namespace {

std::optional<std::array<double, 3>> readKey(Context& context, const ast::Assignment& a, const dey::GeneratorKey& key) {
    switch (key.type) {
    case dey::GeneratorKeyType::Number:
        if (auto v = readNumber(context, a, key.min, key.max)) return std::array<double, 3>{*v, 0, 0};
        return std::nullopt;
    case dey::GeneratorKeyType::Integer:
        if (auto v = readInteger(context, a, int64_t(key.min), int64_t(key.max)))
            return std::array<double, 3>{double(*v), 0, 0};
        return std::nullopt;
    case dey::GeneratorKeyType::Vec3: return readNumberVec3(context, a, key.min, key.max);
    }
    return std::nullopt;
}

// The thesis samples each parameter on a grid from its minimum; other values work but are
// outside the ranges it evaluated, so they warn rather than fail.
void warnOffGrid(Context& context, const ast::Assignment& a, const dey::GeneratorKey& key, double value) {
    if (key.step <= 0) return;
    const double steps = (value - key.min) / key.step;
    if (std::fabs(steps - std::round(steps)) <= 1e-6 * std::max(1.0, std::fabs(steps))) return;
    context.diagnostics.warning("W0205", a.value.loc,
                                fmt::format("'{}' = {} is off the thesis's sampling grid ({} + n * {})", key.name,
                                            formatNumber(value), formatNumber(key.min), formatNumber(key.step)));
}

// Every generator takes `material = NAME;`: the material its pipeline stages write unless the
// stage names its own.

struct CheckedFeature {
    Field field;
    std::optional<Field> stampField; // CheckedFeatures::stampFields
    std::optional<uint8_t> material;
};

// The generator an L-system's carve uses; the others are dey:: records.
constexpr std::string_view kLsystemCave = "lsystem_cave";

std::optional<CheckedFeature> checkFeature(Context& context, const ast::FeatureDecl& decl, const World& world,
                                           const ast::File& file, const std::vector<CheckedLsystem>& lsystems) {
    const ast::Block& body = decl.body;
    const uint32_t seed = world.seed;
    if (body.kind == kLsystemCave) {
        std::optional<CheckedLsystemCave> cave = checkLsystemCave(context, decl, world, file, lsystems);
        if (!cave) return std::nullopt;
        return CheckedFeature{std::move(cave->field), std::move(cave->stampField), cave->material};
    }
    const dey::GeneratorInfo* info = dey::findGenerator(body.kind);
    if (info == nullptr) {
        std::vector<std::string_view> names;
        for (const dey::GeneratorInfo& generator : dey::generators()) names.push_back(generator.name);
        names.push_back(kLsystemCave);
        names.push_back(kSpeleothemsGenerator);
        context.diagnostics.error("E0002", body.loc,
                                  fmt::format("unknown generator '{}'{}", body.kind, suggestOrList(body.kind, names)));
        return std::nullopt;
    }
    const std::string where = fmt::format("'{}' feature", info->name);
    checkLabel(context, body, false);
    rejectUnexpectedMembers(context, body, where, {});
    std::vector<std::string_view> keyNames;
    for (const dey::GeneratorKey& key : info->keys) keyNames.push_back(key.name);
    keyNames.push_back(kMaterialKey);
    BlockKeys keys(context, body, where, keyNames);

    CheckedFeature out;
    dey::GeneratorParams params;
    bool ok = true;
    if (const ast::Assignment* a = keys.find(kMaterialKey)) {
        out.material = readMaterialKey(context, *a);
        ok = out.material.has_value();
    }
    for (const dey::GeneratorKey& key : info->keys) {
        const ast::Assignment* a = key.required ? keys.require(key.name) : keys.find(key.name);
        if (a == nullptr) {
            ok = ok && !key.required;
            if (!key.required && !key.override) params.set(key.name, key.value);
            continue;
        }
        auto value = readKey(context, *a, key);
        if (!value) {
            ok = false;
            continue;
        }
        if (key.type != dey::GeneratorKeyType::Vec3) warnOffGrid(context, *a, key, (*value)[0]);
        params.set(key.name, *value);
    }
    if (!ok) return std::nullopt;
    if (auto problem = info->validate(params)) {
        const ast::Assignment* a = keys.find(problem->key);
        context.diagnostics.error("E0007", a ? a->value.loc : body.loc, problem->message);
        return std::nullopt;
    }
    out.field = info->build(params, seed);
    Field& field = out.field;
    field.name = decl.name;
    field.loc = decl.loc;
    for (FieldNode& node : field.nodes) node.loc = body.loc;
    return out;
}

} // namespace

CheckedFeatures checkFeatures(Context& context, const ast::File& file, const std::vector<std::string>& stageNames,
                              const World& world, const std::vector<CheckedLsystem>& lsystems) {
    CheckedFeatures out;
    std::map<std::string, SourceLoc> names;
    for (const ast::FieldDecl& field : file.fields) names.emplace(field.name, field.loc);
    for (const ast::FeatureDecl& decl : file.features) {
        auto [it, inserted] = names.emplace(decl.name, decl.loc);
        if (!inserted)
            context.diagnostics.error("E0003", decl.loc,
                                      fmt::format("a field or feature named '{}' already exists", decl.name),
                                      {{it->second, "first declared here"}});
        else if (decl.name == "start" || std::find(stageNames.begin(), stageNames.end(), decl.name) != stageNames.end())
            context.diagnostics.error("E0003", decl.loc,
                                      fmt::format("'{}' already names a pipeline stage (a grammar or 'start')",
                                                  decl.name));
        if (decl.body.kind == kSpeleothemsGenerator) {
            if (std::optional<SpeleothemStage> stage = checkSpeleothems(context, decl, out.fields))
                out.speleothems.push_back(std::move(*stage));
            continue;
        }
        std::optional<CheckedFeature> feature = checkFeature(context, decl, world, file, lsystems);
        out.materials.push_back(feature ? feature->material : std::nullopt);
        if (!feature) continue;
        out.fields.push_back(std::move(feature->field));
        out.stampFields.push_back(std::move(feature->stampField));
    }
    return out;
}

} // namespace voxc::check
